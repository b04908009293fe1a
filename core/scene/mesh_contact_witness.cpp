#include "core/scene/mesh_contact_witness.h"

#include <fcl/fcl.h>

#include <algorithm>

namespace demoplan {

namespace {

using Vec = Eigen::Vector3d;
using Triangle3 = std::array<Vec, 3>;
using Model = fcl::BVHModel<fcl::OBBRSSd>;

// Edge u-v through triangle t (see triangles_certainly_cross), with margin m.
bool edge_crosses(const Vec& u, const Vec& v, const Triangle3& t, double m) {
  const Vec n = (t[1] - t[0]).cross(t[2] - t[0]);
  const double area2 = n.norm();
  if (!(area2 > 0.0)) return false;
  const Vec normal = n / area2;
  const double du = normal.dot(u - t[0]), dv = normal.dot(v - t[0]);
  if (!((du >= m && dv <= -m) || (du <= -m && dv >= m))) return false;
  const Vec x = u + (v - u) * (du / (du - dv));  // on the plane
  for (int i = 0; i < 3; ++i) {
    const Vec e = t[(i + 1) % 3] - t[i];
    // How far x lies inside the edge's line, times the edge's length.
    if (!(normal.dot(e.cross(x - t[i])) >= m * e.norm())) return false;
  }
  return true;
}

bool edges_cross(const Triangle3& edges_of, const Triangle3& t, double m) {
  for (int i = 0; i < 3; ++i)
    if (edge_crosses(edges_of[i], edges_of[(i + 1) % 3], t, m)) return true;
  return false;
}

const Model* triangle_model(const fcl::CollisionObjectd& o) {
  const auto* m = dynamic_cast<const Model*>(o.collisionGeometry().get());
  return m && m->getModelType() == fcl::BVH_MODEL_TRIANGLES ? m : nullptr;
}

// FCL tests two meshes in the first one's frame, the second's triangles moved by their
// relative pose (MeshCollisionTraversalNodeOBBRSS); so do these.
struct RelativePose {
  const Model* a = nullptr;
  const Model* b = nullptr;
  fcl::Transform3d b_in_a;

  RelativePose(const fcl::CollisionObjectd& oa, const fcl::CollisionObjectd& ob)
      : a(triangle_model(oa)), b(triangle_model(ob)),
        b_in_a(oa.getTransform().inverse(Eigen::Isometry) * ob.getTransform()) {}

  bool valid() const { return a && b; }

  std::array<Eigen::Vector3f, 3> points() const {
    const double r = b->aabb_radius;
    const Vec c = b->aabb_center;
    return {(b_in_a * c).cast<float>(), (b_in_a * (c + Vec(r, 0, 0))).cast<float>(),
            (b_in_a * (c + Vec(0, r, 0))).cast<float>()};
  }

  bool cross(int ta, int tb) const {
    const fcl::Triangle& p = a->tri_indices[ta];
    const fcl::Triangle& q = b->tri_indices[tb];
    return triangles_certainly_cross({a->vertices[p[0]], a->vertices[p[1]], a->vertices[p[2]]},
                                     {b_in_a * b->vertices[q[0]], b_in_a * b->vertices[q[1]], b_in_a * b->vertices[q[2]]});
  }
};

}  // namespace

bool triangles_certainly_cross(const Triangle3& p, const Triangle3& q) {
  double far = 0.0;
  for (const auto* t : {&p, &q})
    for (const Vec& x : *t) far = std::max(far, x.norm());
  const double m = 1e-6 + 1e-9 * far;
  return edges_cross(p, q, m) || edges_cross(q, p, m);
}

bool MeshContactWitnesses::prove(const fcl::CollisionObjectd& a, const fcl::CollisionObjectd& b) {
  if (witnesses_.empty()) return false;
  const RelativePose rel(a, b);
  if (!rel.valid()) return false;
  const auto now = rel.points();
  const float near2 = static_cast<float>(kNear * kNear);
  int tries = 0;
  for (size_t i = 0; i < witnesses_.size(); ++i) {
    const Witness& w = witnesses_[i];
    if ((w.pose[0] - now[0]).squaredNorm() > near2 || (w.pose[1] - now[1]).squaredNorm() > near2 ||
        (w.pose[2] - now[2]).squaredNorm() > near2)
      continue;
    if (rel.cross(w.ta, w.tb)) {
      // Pairs that keep proving move to the front: deep crossings prove over wide ranges of poses.
      std::rotate(witnesses_.begin(), witnesses_.begin() + i, witnesses_.begin() + i + 1);
      return true;
    }
    if (++tries == kTries) return false;
  }
  return false;
}

void MeshContactWitnesses::learn(const fcl::CollisionObjectd& a, int ta, const fcl::CollisionObjectd& b, int tb) {
  const RelativePose rel(a, b);
  if (!rel.valid() || ta < 0 || tb < 0 || ta >= rel.a->num_tris || tb >= rel.b->num_tris || !rel.cross(ta, tb))
    return;
  const Witness w{ta, tb, rel.points()};
  // New pairs go in the middle, ahead of those that have not proved for longest (the last one
  // is dropped), behind those that proved lately.
  if (static_cast<int>(witnesses_.size()) == kCapacity) witnesses_.pop_back();
  witnesses_.insert(witnesses_.begin() + witnesses_.size() / 2, w);
}

}  // namespace demoplan
