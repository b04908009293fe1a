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

}  // namespace

std::string base_clearance(const Scene& scene, double lift) {
  if (!scene.robot.fixed_base) return "";
  const Pose up(Eigen::Translation3d(0, 0, lift));
  std::vector<Placed> base, furniture;
  const RobotModel& model = scene.robot.model;
  PoseVector links;
  forward_kinematics(model, scene.robot.initial_configuration, scene.robot.base, links);
  const std::vector<int> body = model.rigid_bodies();
  for (size_t l = 0; l < model.links.size(); ++l)
    if (body[l] == 0)
      for (const Geometry& g : model.links[l].collisions)
        base.push_back({fcl_object(g), up * links[l] * g.origin, "the robot's " + model.links[l].name});
  for (const SceneFurniture& f : scene.furniture)
    for (size_t l = 0; l < f.model.links.size(); ++l)
      for (const Geometry& g : f.model.links[l].collisions) {
        if (f.kind == kSupportBoxKind) base.push_back({fcl_object(g), up * f.link_poses[l] * g.origin, "its support box"});
        else furniture.push_back({fcl_object(g), f.link_poses[l] * g.origin, f.name + "/" + f.model.links[l].name});
      }
  for (const Placed& b : base) {
    const fcl::CollisionObjectd a = at(b);
    for (const Placed& f : furniture) {
      const fcl::CollisionObjectd o = at(f);
      if (!a.getAABB().overlap(o.getAABB())) continue;
      fcl::CollisionRequestd request;
      fcl::CollisionResultd result;
      if (fcl::collide(&a, &o, request, result) > 0) return b.name + " is inside " + f.name;
    }
  }
  return "";
}

}  // namespace demoplan
