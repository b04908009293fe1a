#include "core/placement/base_clearance.h"

#include <fcl/fcl.h>

#include "core/demo/benchmark_scene.h"
#include "core/model/kinematics.h"
#include "core/scene/fcl_object.h"

namespace demoplan {

namespace {

struct Placed {
  std::shared_ptr<const fcl::CollisionObjectd> prototype;
  Pose pose;
  std::string name;
};

fcl::CollisionObjectd at(const Placed& p) {
  fcl::CollisionObjectd o = *p.prototype;
  o.setTransform(p.pose);
  o.computeAABB();
  return o;
}

bool collide(const fcl::CollisionObjectd& a, const fcl::CollisionObjectd& b) {
  if (!a.getAABB().overlap(b.getAABB())) return false;
  fcl::CollisionRequestd request;
  fcl::CollisionResultd result;
  return fcl::collide(&a, &b, request, result) > 0;
}

// A thin slab of `thickness` under (or over) a point: probes what the point stands on.
fcl::CollisionObjectd slab(const Eigen::Vector3d& p, double thickness, bool below) {
  auto box = std::make_shared<fcl::Boxd>(0.004, 0.004, thickness);
  fcl::CollisionObjectd o(box, Eigen::Matrix3d::Identity(), p + Eigen::Vector3d(0, 0, (below ? -1 : 1) * (thickness / 2 + 1e-4)));
  o.computeAABB();
  return o;
}

}  // namespace

int furniture_under_base(const Scene& scene, double tolerance) {
  // Its top is at the base: something just under the base's origin, nothing just over it. The
  // geometry itself is probed (FCL's AABB of a turned object is its bounding sphere's).
  const Eigen::Vector3d p = scene.robot.base.translation();
  const fcl::CollisionObjectd under = slab(p, tolerance, true), over = slab(p, tolerance, false);
  for (size_t i = 0; i < scene.furniture.size(); ++i) {
    const SceneFurniture& f = scene.furniture[i];
    if (f.kind == kSupportBoxKind) continue;
    bool touches = false, covers = false;
    for (size_t l = 0; l < f.model.links.size(); ++l)
      for (const Geometry& g : f.model.links[l].collisions) {
        const fcl::CollisionObjectd o = at({fcl_object(g), f.link_poses[l] * g.origin, ""});
        touches |= collide(under, o);
        covers |= collide(over, o);
      }
    if (touches && !covers) return static_cast<int>(i);
  }
  return -1;
}

namespace {
// The furniture `under` the base (furniture_under_base) when it is a pedestal, else -1.
int pedestal_of(const Scene& scene, int under) {
  if (under < 0) return -1;
  for (const ContactSurface& c : scene.furniture[static_cast<size_t>(under)].srdf.contacts)
    if (!c.polygons.empty()) return -1;  // parts may rest on it: it stays
  return under;
}
}  // namespace

int robot_pedestal(const Scene& scene) { return pedestal_of(scene, furniture_under_base(scene)); }

std::string base_clearance(const Scene& scene, double lift) {
  if (!scene.robot.fixed_base) return "";
  const Pose up(Eigen::Translation3d(0, 0, lift));
  std::vector<Placed> base, furniture;
  bool support_box = false;
  for (const SceneFurniture& f : scene.furniture) support_box |= f.kind == kSupportBoxKind;
  const double z = scene.robot.base.translation().z();
  const int under = furniture_under_base(scene, lift);
  if (!support_box && z > lift && under < 0)
    return "the robot's base stands on nothing: " + std::to_string(static_cast<int>(std::lround(z * 1000))) +
           " mm above the floor with no furniture top under it";
  const RobotModel& model = scene.robot.model;
  PoseVector links;
  forward_kinematics(model, scene.robot.initial_configuration, scene.robot.base, links);
  const std::vector<int> body = model.rigid_bodies();
  for (size_t l = 0; l < model.links.size(); ++l)
    if (body[l] == 0)
      for (const Geometry& g : model.links[l].collisions)
        base.push_back({fcl_object(g), up * links[l] * g.origin, "the robot's " + model.links[l].name});
  const int pedestal = pedestal_of(scene, under);
  for (size_t i = 0; i < scene.furniture.size(); ++i) {
    const SceneFurniture& f = scene.furniture[i];
    for (size_t l = 0; l < f.model.links.size(); ++l)
      for (const Geometry& g : f.model.links[l].collisions) {
        if (f.kind == kSupportBoxKind) base.push_back({fcl_object(g), up * f.link_poses[l] * g.origin, "its support box"});
        else if (static_cast<int>(i) == pedestal) base.push_back({fcl_object(g), up * f.link_poses[l] * g.origin, "its pedestal '" + f.name + "'"});
        else furniture.push_back({fcl_object(g), f.link_poses[l] * g.origin, f.name + "/" + f.model.links[l].name});
      }
  }
  for (const Placed& b : base) {
    const fcl::CollisionObjectd a = at(b);
    for (const Placed& f : furniture) {
      if (collide(a, at(f))) return b.name + " is inside " + f.name;
    }
  }
  return "";
}

}  // namespace demoplan
