#include "core/scene/collision_checker.h"

#include <fcl/fcl.h>

#include <algorithm>
#include <cassert>
#include <cmath>
#include <cstdint>
#include <limits>
#include <set>
#include <thread>
#include <unordered_map>

#include "core/error.h"
#include "core/scene/bvh_cache.h"
#include "core/scene/fcl_object.h"
#include "core/scene/geometry_bounds.h"
#include "core/scene/joint_pair_table.h"
#include "core/scene/mesh_contact_witness.h"

namespace demoplan {

using fcl::CollisionObjectd;

void AllowedContacts::allow_gripper(const Scene& scene, int object) {
  // The hand, the fingers and anything mounted on them.
  for (int l : scene.robot.model.subtree_links(scene.robot.gripper_link)) allow_object_link(object, l);
}

bool AllowedContacts::allows_object_link(int object, int link) const {
  return std::find(object_link.begin(), object_link.end(), std::make_pair(object, link)) !=
         object_link.end();
}

bool AllowedContacts::allows_object_furniture(int object, int furniture) const {
  return std::find(object_furniture.begin(), object_furniture.end(),
                   std::make_pair(object, furniture)) != object_furniture.end();
}

namespace collision_detail {

enum class Owner { Robot, Object, Furniture };

struct GeomInfo {
  Owner owner = Owner::Robot;
  int index = -1;  // robot link, object index or furniture index
  int link = -1;   // link within the owner's model
  Pose local = Pose::Identity();  // in the owner's link frame (objects: in the object frame)
  std::string name;
  bool world_fixed = false;    // robot geometry on the root of a fixed-base robot
  bool robot_ignored = false;  // furniture geometry the robot never collides with
  std::shared_ptr<const CollisionObjectd> prototype;  // at the identity; copied, never placed
  GeometryBound bound;  // for the fast path
  // Where this geometry's world sphere centres are: furniture in Impl::furniture_centres, placed
  // once; robot and object geometries in Workspace::centres, placed per query when first needed
  // (slot indexes Workspace::placed_at).
  int centre_offset = 0;
  int child_offset = 0;  // children's centres, in the same array's children counterpart
  int part_offset = 0;   // moving geometries: into Workspace::child_placed
  int slot = -1;
  int uid = -1;  // unique over robot, object and furniture geometries: keys a pair's witnesses
};

struct Prototype {
  std::shared_ptr<const CollisionObjectd> object;
  GeometryBound bound;
};

// An object at the identity to copy (see bvh_cache.h), and its bounds. A mesh comes fitted from
// the process-wide cache with its spheres (`fitted`); primitives are cheap and belong to this checker.
Prototype make_prototype(const Geometry& g, const SharedMesh& fitted) {
  if (std::holds_alternative<MeshShape>(g.shape)) return {fitted.bvh, mesh_bound(fitted.spheres)};
  GeometryBound bound;
  if (auto* b = std::get_if<BoxShape>(&g.shape)) bound = box_bound(b->size);
  else if (auto* c = std::get_if<CylinderShape>(&g.shape)) bound = cylinder_bound(c->radius, c->length);
  else bound = sphere_bound(std::get<SphereShape>(g.shape).radius);
  return {fcl_object(g), bound};
}

}  // namespace collision_detail
using namespace collision_detail;

struct CollisionData::Workspace {
  PoseVector link_poses;
  PoseList object_poses;
  std::vector<CollisionObjectd> robot;    // one per robot geometry, world transform set per query
  std::vector<CollisionObjectd> objects;  // one per object geometry
  // The moving geometries' world AABBs by GeomInfo::slot, copied once per query: FCL's
  // getAABB and overlap are compiled into libfcl (extern templates), a call each per pair.
  std::vector<fcl::AABBd> boxes;
  fcl::CollisionRequestd request;
  fcl::CollisionResultd result;

  // Object-vs-furniture and object-vs-object results do not depend on the robot. Within a
  // planning state most objects stay put, so a pair found free is remembered until one of its
  // objects moves (or, against furniture, until the allowed contacts change).
  PoseList last_object_tf;                         // per object geometry
  std::vector<char> moved;                         // per object geometry, this query
  std::vector<char> world_free;                    // per object geometry
  std::vector<std::vector<int>> world_allowed;     // allowed furniture when world_free was set
  std::vector<char> pair_free;                     // object geometry pairs, row-major

  // Fast path: world sphere centres of the robot and object geometries, placed when a pair
  // first needs them in a query (GeomInfo::centre_offset, slot).
  std::vector<Eigen::Vector3d> centres, children;
  std::vector<std::uint64_t> placed_at;     // per slot: the query the whole's centre was placed for
  std::vector<std::uint64_t> parts_placed;  // per slot: the same for the parts' centres
  std::vector<std::uint64_t> child_placed;  // per part of every geometry: the same for its children
  std::uint64_t query = 0;

  // Mesh-mesh pairs FCL found touching: triangle pairs that may prove the next contact
  // (mesh_contact_witness.h), keyed by the pair's GeomInfo::uid.
  std::unordered_map<std::uint64_t, MeshContactWitnesses> witnesses;

  // Robot pairs whose exact test waits until every cheap test of the query has had its say
  // (Query::defer_exact); reused between queries.
  struct ExactTest {
    CollisionObjectd* a;
    const GeomInfo* ia;
    CollisionObjectd* b;
    const GeomInfo* ib;
    MeshContactWitnesses* witnesses;
  };
  std::vector<ExactTest> waiting;
};

CollisionData::CollisionData() = default;
CollisionData::~CollisionData() = default;
CollisionData::CollisionData(CollisionData&&) noexcept = default;
CollisionData& CollisionData::operator=(CollisionData&&) noexcept = default;

using Workspace = CollisionData::Workspace;

struct CollisionChecker::Impl {
  CollisionOptions options;
  std::vector<GeomInfo> robot, objects, furniture;
  std::vector<Eigen::Vector3d> furniture_centres, furniture_children;  // world, fixed
  size_t moving_centres = 0, moving_children = 0, moving_parts = 0;    // Workspace sizes
  std::vector<CollisionObjectd> robot_proto, object_proto;
  std::vector<std::unique_ptr<CollisionObjectd>> furniture_objects;
  fcl::DynamicAABBTreeCollisionManagerd world;
  std::vector<std::pair<int, int>> self_pairs;  // robot geometry indices
  // Per self pair: its distance table when one or two joints move it (null otherwise).
  std::vector<std::unique_ptr<JointPairTable>> self_tables;

  // Collects results of one query; shared by the broad-phase callback and the pair loops.
  struct Query {
    const Impl* impl;
    Workspace* data;
    const AllowedContacts* allowed;
    std::vector<CollisionPair>* all;  // null: stop at the first hit
    CollisionPair first;
    bool hit = false;
    int hits = 0;
    const GeomInfo* query_info = nullptr;  // broad phase: the moving geometry asked about
    CollisionObjectd* query_object = nullptr;
    const Eigen::VectorXd* q = nullptr;    // the robot's configuration
    // When only the answer is asked for, any colliding pair will do: the robot's pairs that no
    // bound separates or proves touching wait in Workspace::waiting, so that a cheap proof
    // further on spares their exact tests (finish() runs them when none came).
    bool defer_exact = false;

    bool done() const { return hit && !all; }

    // `table`: a self pair's distance table, asked when the bounds cannot separate the pair
    // (measuring a node costs more than FCL's query; only pairs that reach FCL fill it).
    // `may_wait`: the pair's exact test may be deferred (robot pairs; object pairs feed the
    // caches of Workspace::pair_free and world_free, which need their answer now).
    void narrow(CollisionObjectd& a, const GeomInfo& ia, CollisionObjectd& b, const GeomInfo& ib,
                const JointPairTable* table = nullptr, bool may_wait = false) {
      bool touch = false;
      if (impl->options.fast_path) {
        const PlacedBound pa = impl->placed(*data, a, ia), pb = impl->placed(*data, b, ib);
        if (certainly_separated(pa, pb) || (table && table->certainly_free(*q))) return;
        touch = certainly_touching(pa, pb);
      }
      MeshContactWitnesses* witnesses = nullptr;
      if (!touch && impl->options.fast_path && ia.bound.kind == GeometryBound::Kind::Mesh &&
          ib.bound.kind == GeometryBound::Kind::Mesh) {
        witnesses = &data->witnesses[(std::uint64_t(ia.uid) << 32) | std::uint32_t(ib.uid)];
        touch = witnesses->prove(a, b);
      }
      if (!touch) {
        if (defer_exact && may_wait) {
          data->waiting.push_back({&a, &ia, &b, &ib, witnesses});
          return;
        }
        if (!exact(a, b, witnesses)) return;
      }
      record(ia, ib);
    }

    // The deferred exact tests, in the order they were met, until one collides.
    void finish() {
      for (const auto& t : data->waiting) {
        if (hit) break;
        if (exact(*t.a, *t.b, t.witnesses)) record(*t.ia, *t.ib);
      }
      data->waiting.clear();
    }

    bool exact(CollisionObjectd& a, CollisionObjectd& b, MeshContactWitnesses* witnesses) {
      data->result.clear();
      if (fcl::collide(&a, &b, data->request, data->result) == 0) return false;
      if (witnesses && data->result.numContacts() > 0) {
        const fcl::Contactd& c = data->result.getContact(0);
        if (c.o1 == a.collisionGeometry().get()) witnesses->learn(a, c.b1, b, c.b2);
      }
      return true;
    }

    void record(const GeomInfo& ia, const GeomInfo& ib) {
      CollisionPair p{ia.name, ib.name};
      if (!hit) first = p;
      hit = true;
      ++hits;
      if (all) all->push_back(std::move(p));
    }
  };

  PlacedBound placed(Workspace& d, const CollisionObjectd& o, const GeomInfo& g) const {
    if (g.owner == Owner::Furniture)  // all placed at construction: never written
      return {&g.bound, &o.getTransform(), const_cast<Eigen::Vector3d*>(furniture_centres.data()) + g.centre_offset,
              const_cast<Eigen::Vector3d*>(furniture_children.data()) + g.child_offset, nullptr, 0, nullptr};
    Eigen::Vector3d* c = d.centres.data() + g.centre_offset;
    if (d.placed_at[g.slot] != d.query) {
      place_whole_centre(g.bound, o.getTransform(), c);
      d.placed_at[g.slot] = d.query;
    }
    return {&g.bound, &o.getTransform(), c, d.children.data() + g.child_offset, d.child_placed.data() + g.part_offset,
            d.query, d.parts_placed.data() + g.slot};
  }

  bool skip_furniture(const GeomInfo& moving, const GeomInfo& f, const AllowedContacts& allowed) const {
    if (moving.owner == Owner::Robot) return moving.world_fixed || f.robot_ignored;
    return allowed.allows_object_furniture(moving.index, f.index);
  }

  static bool broadphase_callback(CollisionObjectd* o1, CollisionObjectd* o2, void* cdata) {
    auto* q = static_cast<Query*>(cdata);
    CollisionObjectd* other = (o1 == q->query_object) ? o2 : o1;
    const auto* f = static_cast<const GeomInfo*>(other->getUserData());
    if (q->impl->skip_furniture(*q->query_info, *f, *q->allowed)) return false;
    q->narrow(*q->query_object, *q->query_info, *other, *f, nullptr, q->query_info->owner == Owner::Robot);
    return q->done();
  }

  void against_world(Query& q, CollisionObjectd& obj, const GeomInfo& info) const {
    q.query_info = &info;
    q.query_object = &obj;
    world.collide(&obj, &q, &Impl::broadphase_callback);
  }

  void place(const Scene& scene, const SceneState& state, Workspace& d) const {
    ++d.query;  // every geometry's world spheres are stale
    forward_kinematics(scene.robot.model, state.q, scene.robot.base, d.link_poses);
    d.object_poses = state.objects;
    for (const auto& a : state.attachments) d.object_poses[a.object] = d.link_poses[a.link] * a.link_T_object;
    for (size_t i = 0; i < robot.size(); ++i) {
      d.robot[i].setTransform(d.link_poses[robot[i].link] * robot[i].local);
      d.robot[i].computeAABB();
      d.boxes[robot[i].slot] = d.robot[i].getAABB();
    }
    const size_t n = objects.size();
    if (d.last_object_tf.size() != n) {
      d.last_object_tf.assign(n, Pose(Eigen::Matrix4d::Constant(std::nan(""))));
      d.moved.assign(n, 1);
      d.world_free.assign(n, 0);
      d.world_allowed.assign(n, {});
      d.pair_free.assign(n * n, 0);
    }
    for (size_t i = 0; i < n; ++i) {
      const Pose tf = d.object_poses[objects[i].index] * objects[i].local;
      d.moved[i] = !(tf.matrix().array() == d.last_object_tf[i].matrix().array()).all();
      if (d.moved[i]) {
        d.last_object_tf[i] = tf;
        d.world_free[i] = 0;
        for (size_t k = 0; k < n; ++k) d.pair_free[i * n + k] = d.pair_free[k * n + i] = 0;
      }
      d.objects[i].setTransform(tf);
      d.objects[i].computeAABB();
      d.boxes[objects[i].slot] = d.objects[i].getAABB();
    }
  }

  static std::vector<int> allowed_furniture(const AllowedContacts& allowed, int object) {
    std::vector<int> out;
    for (const auto& [o, f] : allowed.object_furniture)
      if (o == object) out.push_back(f);
    return out;
  }

  // Every pair the benchmark checks, once, in the order that meets collisions soonest: moving
  // robot links against the world (random configurations hit the furniture most often), robot
  // self pairs, then each object against the robot's links, the later objects and the world.
  // The visitor decides what a pair costs and when to stop (Visitor::done()); collision and
  // distance queries share this walk.
  template <class Visitor>
  void visit_pairs(Workspace& d, const AllowedContacts& allowed, Visitor& v) const {
    for (size_t i = 0; i < robot.size() && !v.done(); ++i)
      if (!robot[i].world_fixed) v.robot_world(d.robot[i], robot[i]);
    for (size_t k = 0; k < self_pairs.size(); ++k) {
      if (v.done()) return;
      const auto [i, j] = self_pairs[k];
      v.self_pair(k, d.robot[i], robot[i], d.robot[j], robot[j]);
    }
    for (size_t o = 0; o < objects.size() && !v.done(); ++o) {
      const GeomInfo& oi = objects[o];
      for (size_t r = 0; r < robot.size() && !v.done(); ++r)
        if (!allowed.allows_object_link(oi.index, robot[r].link)) v.object_robot(o, d.objects[o], oi, d.robot[r], robot[r]);
      for (size_t p = o + 1; p < objects.size() && !v.done(); ++p)
        if (objects[p].index != oi.index) v.object_pair(o, p);
      if (v.done()) return;
      v.object_world(o, d.objects[o], oi);
    }
  }

  // The collision query's visitor: AABB overlap first, exact narrow phase only then, and object
  // results cached while the objects stand still (Workspace::pair_free, world_free).
  struct CollisionVisitor {
    const Impl& impl;
    Query& q;
    Workspace& d;
    bool done() const { return q.done(); }
    void robot_world(CollisionObjectd& obj, const GeomInfo& info) { impl.against_world(q, obj, info); }
    bool boxes_overlap(const GeomInfo& ia, const GeomInfo& ib) const {
      const fcl::AABBd &a = d.boxes[ia.slot], &b = d.boxes[ib.slot];
      for (int k = 0; k < 3; ++k)  // as fcl::AABB::overlap: touching boxes overlap
        if (a.min_[k] > b.max_[k] || b.min_[k] > a.max_[k]) return false;
      return true;
    }
    void self_pair(size_t k, CollisionObjectd& a, const GeomInfo& ia, CollisionObjectd& b, const GeomInfo& ib) {
      if (boxes_overlap(ia, ib)) q.narrow(a, ia, b, ib, impl.self_tables[k].get(), true);
    }
    void pair(CollisionObjectd& a, const GeomInfo& ia, CollisionObjectd& b, const GeomInfo& ib) {
      if (boxes_overlap(ia, ib)) q.narrow(a, ia, b, ib);
    }
    void object_robot(size_t, CollisionObjectd& a, const GeomInfo& ia, CollisionObjectd& b, const GeomInfo& ib) {
      pair(a, ia, b, ib);
    }
    void object_pair(size_t o, size_t p) {
      const size_t n = impl.objects.size();
      if (d.pair_free[o * n + p]) return;
      const int before = q.hits;
      pair(d.objects[o], impl.objects[o], d.objects[p], impl.objects[p]);
      d.pair_free[o * n + p] = q.hits == before;
    }
    void object_world(size_t o, CollisionObjectd& obj, const GeomInfo& info) {
      std::vector<int> allowed = allowed_furniture(*q.allowed, info.index);
      if (d.world_free[o] && d.world_allowed[o] == allowed) return;
      const int before = q.hits;
      impl.against_world(q, obj, info);
      d.world_free[o] = q.hits == before;
      d.world_allowed[o] = std::move(allowed);
    }
  };

  void run(Query& q) const {
    CollisionVisitor v{*this, q, *q.data};
    q.data->waiting.clear();  // none left by a query that threw
    visit_pairs(*q.data, *q.allowed, v);
    q.finish();
  }
};

CollisionChecker::CollisionChecker(const Scene& scene, CollisionOptions options)
    : scene_(scene), impl_(std::make_unique<Impl>()) {
  impl_->options = options;
  // collision_meshes lists the meshes in the order the geometries are added below.
  const auto meshes = collision_meshes(scene);
  const std::vector<SharedMesh> fitted =
      shared_meshes(meshes, static_cast<int>(std::max(1u, std::thread::hardware_concurrency())));
  size_t next_mesh = 0;
  auto add = [&](std::vector<GeomInfo>& list, GeomInfo info, const Geometry& g) {
    static const SharedMesh none;
    const auto* m = std::get_if<MeshShape>(&g.shape);
    if (m && m->mesh) assert(meshes[next_mesh].first == m->mesh.get());
    Prototype p = make_prototype(g, m && m->mesh ? fitted[next_mesh++] : none);
    info.prototype = std::move(p.object);
    info.bound = std::move(p.bound);
    list.push_back(std::move(info));
  };

  // Robot.
  const RobotModel& rm = scene.robot.model;
  const std::vector<int> body = rm.rigid_bodies();
  for (size_t l = 0; l < rm.links.size(); ++l) {
    for (const auto& g : rm.links[l].collisions) {
      GeomInfo info;
      info.owner = Owner::Robot;
      info.index = info.link = static_cast<int>(l);
      info.local = g.origin;
      info.name = "robot/" + rm.links[l].name;
      info.world_fixed = scene.robot.fixed_base && body[l] == 0;
      add(impl_->robot, std::move(info), g);
    }
  }
  auto link_geometry = [](const GeomInfo& g) {
    return LinkGeometry{g.link, g.local, g.prototype, &g.bound};
  };
  auto adjacent = [&](int a, int b) {
    // Bodies joined by one moving joint: the parent joint of one body's top link hangs off the other.
    auto joined = [&](int child_body, int parent_body) {
      const int pj = rm.links[child_body].parent_joint;
      return pj >= 0 && body[rm.joints[pj].parent_link] == parent_body;
    };
    return joined(body[a], body[b]) || joined(body[b], body[a]);
  };
  for (size_t i = 0; i < impl_->robot.size(); ++i) {
    for (size_t j = i + 1; j < impl_->robot.size(); ++j) {
      const auto& a = impl_->robot[i];
      const auto& b = impl_->robot[j];
      if (body[a.link] == body[b.link]) continue;
      if (a.world_fixed && b.world_fixed) continue;
      if (scene.robot.srdf.collision_disabled(rm.links[a.link].name, rm.links[b.link].name)) continue;
      if (options.skip_adjacent_links && adjacent(a.link, b.link)) continue;
      impl_->self_pairs.emplace_back(static_cast<int>(i), static_cast<int>(j));
      impl_->self_tables.push_back(options.fast_path ? JointPairTable::make(rm, link_geometry(a), link_geometry(b))
                                                     : nullptr);
    }
  }

  // Objects: geometry relative to the object's root frame.
  for (size_t o = 0; o < scene.objects.size(); ++o) {
    const RobotModel& om = scene.objects[o].model;
    PoseVector poses;
    forward_kinematics(om, Eigen::VectorXd::Zero(om.nq), Pose::Identity(), poses);
    for (size_t l = 0; l < om.links.size(); ++l) {
      for (const auto& g : om.links[l].collisions) {
        GeomInfo info;
        info.owner = Owner::Object;
        info.index = static_cast<int>(o);
        info.link = static_cast<int>(l);
        info.local = poses[l] * g.origin;
        info.name = "object/" + scene.objects[o].id;
        add(impl_->objects, std::move(info), g);
      }
    }
  }

  // Furniture: fixed in the world, registered once in the broad phase.
  for (size_t f = 0; f < scene.furniture.size(); ++f) {
    const auto& fu = scene.furniture[f];
    for (size_t l = 0; l < fu.model.links.size(); ++l) {
      const auto& link = fu.model.links[l];
      const bool ignored = std::find(fu.robot_ignored_links.begin(), fu.robot_ignored_links.end(),
                                     link.name) != fu.robot_ignored_links.end();
      for (const auto& g : link.collisions) {
        GeomInfo info;
        info.owner = Owner::Furniture;
        info.index = static_cast<int>(f);
        info.link = static_cast<int>(l);
        info.local = fu.link_poses[l] * g.origin;
        info.name = fu.name + "/" + link.name;
        info.robot_ignored = ignored;
        add(impl_->furniture, std::move(info), g);
      }
    }
  }
  // Sphere slots: the moving geometries' in each Workspace, the furniture's here, placed once.
  int slot = 0;
  for (auto* list : {&impl_->robot, &impl_->objects})
    for (auto& info : *list) {
      info.slot = slot++;
      info.centre_offset = static_cast<int>(impl_->moving_centres);
      info.child_offset = static_cast<int>(impl_->moving_children);
      info.part_offset = static_cast<int>(impl_->moving_parts);
      impl_->moving_centres += info.bound.centre_count();
      impl_->moving_children += info.bound.child_count();
      impl_->moving_parts += info.bound.part_count();
    }
  int uid = 0;
  for (auto* list : {&impl_->robot, &impl_->objects, &impl_->furniture})
    for (auto& info : *list) info.uid = uid++;
  for (auto& info : impl_->furniture) {
    info.centre_offset = static_cast<int>(impl_->furniture_centres.size());
    info.child_offset = static_cast<int>(impl_->furniture_children.size());
    impl_->furniture_centres.resize(impl_->furniture_centres.size() + info.bound.centre_count());
    impl_->furniture_children.resize(impl_->furniture_children.size() + info.bound.child_count());
    place_centres(info.bound, info.local, impl_->furniture_centres.data() + info.centre_offset);
    place_children(info.bound, info.local, impl_->furniture_children.data() + info.child_offset);
  }

  // Pointers into impl_->furniture stay valid: the vector is complete now.
  for (auto& info : impl_->furniture) {
    auto obj = std::make_unique<CollisionObjectd>(*info.prototype);
    obj->setTransform(info.local);
    obj->setUserData(&info);
    obj->computeAABB();
    impl_->furniture_objects.push_back(std::move(obj));
  }
  std::vector<CollisionObjectd*> raw;
  for (auto& o : impl_->furniture_objects) raw.push_back(o.get());
  impl_->world.registerObjects(raw);
  impl_->world.setup();

  // Copied into each CollisionData (copying does not touch the shared geometry, unlike
  // constructing, which recomputes its local AABB).
  for (auto& info : impl_->robot) impl_->robot_proto.push_back(*info.prototype);
  for (auto& info : impl_->objects) impl_->object_proto.push_back(*info.prototype);
}

CollisionChecker::~CollisionChecker() = default;

CollisionData CollisionChecker::make_data() const {
  CollisionData d;
  d.w_ = std::make_unique<Workspace>();
  d.w_->robot = impl_->robot_proto;
  d.w_->objects = impl_->object_proto;
  d.w_->centres.resize(impl_->moving_centres);
  d.w_->children.resize(impl_->moving_children);
  d.w_->child_placed.assign(impl_->moving_parts, 0);
  d.w_->placed_at.assign(impl_->robot.size() + impl_->objects.size(), 0);
  d.w_->parts_placed.assign(impl_->robot.size() + impl_->objects.size(), 0);
  d.w_->boxes.resize(impl_->robot.size() + impl_->objects.size());
  return d;
}

size_t CollisionChecker::pair_count() const {
  const auto& I = *impl_;
  size_t moving_robot = 0, robot_visible_furniture = 0;
  for (const auto& r : I.robot) moving_robot += !r.world_fixed;
  for (const auto& f : I.furniture) robot_visible_furniture += !f.robot_ignored;
  size_t object_pairs = 0;
  for (size_t o = 0; o < I.objects.size(); ++o)
    for (size_t p = o + 1; p < I.objects.size(); ++p) object_pairs += I.objects[o].index != I.objects[p].index;
  return I.self_pairs.size() + moving_robot * robot_visible_furniture +
         I.objects.size() * (I.robot.size() + I.furniture.size()) + object_pairs;
}

bool CollisionChecker::in_collision(const SceneState& state, CollisionData& data,
                                    const AllowedContacts& allowed, CollisionPair* hit) const {
  impl_->place(scene_, state, *data.w_);
  Impl::Query q{impl_.get(), data.w_.get(), &allowed, nullptr, {}};
  q.q = &state.q;
  q.defer_exact = !hit && impl_->options.fast_path;
  impl_->run(q);
  if (q.hit && hit) *hit = q.first;
  return q.hit;
}

std::vector<CollisionPair> CollisionChecker::collisions(const SceneState& state, CollisionData& data,
                                                        const AllowedContacts& allowed) const {
  impl_->place(scene_, state, *data.w_);
  std::vector<CollisionPair> all;
  Impl::Query q{impl_.get(), data.w_.get(), &allowed, &all, {}};
  q.q = &state.q;
  impl_->run(q);
  return all;
}

namespace {

struct DistanceQuery {
  const CollisionChecker::Impl* impl;
  const AllowedContacts* allowed;
  DistanceResult best;
  const GeomInfo* query_info = nullptr;
  CollisionObjectd* query_object = nullptr;
  fcl::DistanceRequestd request{true};

  void measure(CollisionObjectd& a, const GeomInfo& ia, CollisionObjectd& b, const GeomInfo& ib) {
    if (a.getAABB().distance(b.getAABB()) >= best.distance) return;
    fcl::DistanceResultd r;
    fcl::distance(&a, &b, request, r);
    if (r.min_distance < best.distance) {
      best.distance = std::max(0.0, r.min_distance);
      best.pair = {ia.name, ib.name};
      best.first_point = r.nearest_points[0];
      best.second_point = r.nearest_points[1];
    }
  }
};

}  // namespace

DistanceResult CollisionChecker::distance(const SceneState& state, CollisionData& data,
                                          const AllowedContacts& allowed) const {
  return min_distance(state, data, allowed, -1);
}

DistanceResult CollisionChecker::object_distance(const SceneState& state, CollisionData& data,
                                                 int object, const AllowedContacts& allowed) const {
  return min_distance(state, data, allowed, object);
}

DistanceResult CollisionChecker::min_distance(const SceneState& state, CollisionData& data,
                                              const AllowedContacts& allowed, int only_object) const {
  const auto pairs = collisions(state, data, allowed);  // also places the scene
  for (const auto& p : pairs)
    if (only_object < 0 || p.first == "object/" + scene_.objects[only_object].id ||
        p.second == "object/" + scene_.objects[only_object].id)
      return {0.0, p, {}, {}};
  const Impl& I = *impl_;
  Workspace& w = *data.w_;
  DistanceQuery q{impl_.get(), &allowed, {}};
  q.best.distance = std::numeric_limits<double>::infinity();
  auto world_callback = [](CollisionObjectd* o1, CollisionObjectd* o2, void* cdata, double& dist) {
    auto* dq = static_cast<DistanceQuery*>(cdata);
    CollisionObjectd* other = (o1 == dq->query_object) ? o2 : o1;
    const auto* f = static_cast<const GeomInfo*>(other->getUserData());
    if (!dq->impl->skip_furniture(*dq->query_info, *f, *dq->allowed))
      dq->measure(*dq->query_object, *dq->query_info, *other, *f);
    dist = dq->best.distance;
    return false;
  };
  auto against_world = [&](CollisionObjectd& obj, const GeomInfo& info) {
    q.query_info = &info;
    q.query_object = &obj;
    I.world.distance(&obj, &q, world_callback);
  };
  // Pairs that involve `only_object` (all pairs when it is -1).
  struct DistanceVisitor {
    const CollisionChecker::Impl& impl;
    Workspace& w;
    DistanceQuery& q;
    decltype(against_world)& world;
    int only_object;
    bool involved(size_t o) const { return only_object < 0 || impl.objects[o].index == only_object; }
    bool done() const { return false; }
    void robot_world(CollisionObjectd& obj, const GeomInfo& info) {
      if (only_object < 0) world(obj, info);
    }
    void self_pair(size_t, CollisionObjectd& a, const GeomInfo& ia, CollisionObjectd& b, const GeomInfo& ib) {
      if (only_object < 0) q.measure(a, ia, b, ib);
    }
    void object_robot(size_t o, CollisionObjectd& a, const GeomInfo& ia, CollisionObjectd& b, const GeomInfo& ib) {
      if (involved(o)) q.measure(a, ia, b, ib);
    }
    void object_pair(size_t o, size_t p) {
      if (involved(o) || involved(p)) q.measure(w.objects[o], impl.objects[o], w.objects[p], impl.objects[p]);
    }
    void object_world(size_t o, CollisionObjectd& obj, const GeomInfo& info) {
      if (involved(o)) world(obj, info);
    }
  };
  DistanceVisitor v{I, w, q, against_world, only_object};
  I.visit_pairs(w, allowed, v);
  return q.best;
}

}  // namespace demoplan
