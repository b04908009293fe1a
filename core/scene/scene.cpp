#include "core/scene/scene.h"

namespace demoplan {

int Scene::object_index(const std::string& id) const {
  for (size_t i = 0; i < objects.size(); ++i)
    if (objects[i].id == id) return static_cast<int>(i);
  return -1;
}

void update_attached_objects(const PoseVector& robot_link_poses, SceneState& state) {
  for (const auto& a : state.attachments)
    state.objects[a.object] = robot_link_poses[a.link] * a.link_T_object;
}

Pose gripper_pose(const Scene& scene, const Eigen::VectorXd& q) {
  const auto& r = scene.robot;
  return link_pose(r.model, q, r.base, r.gripper_link) * r.gripper().pose;
}

Attachment attach_to_gripper(const Scene& scene, const SceneState& state, int object) {
  const auto& r = scene.robot;
  const Pose link = link_pose(r.model, state.q, r.base, r.gripper_link);
  return {object, r.gripper_link, link.inverse() * state.objects[object]};
}

std::vector<std::pair<const TriangleMesh*, Eigen::Vector3d>> collision_meshes(const Scene& scene) {
  std::vector<std::pair<const TriangleMesh*, Eigen::Vector3d>> out;
  auto take = [&](const RobotModel& model) {
    for (const auto& link : model.links)
      for (const auto& g : link.collisions)
        if (const auto* m = std::get_if<MeshShape>(&g.shape); m && m->mesh) out.emplace_back(m->mesh.get(), m->scale);
  };
  take(scene.robot.model);
  for (const auto& o : scene.objects) take(o.model);
  for (const auto& f : scene.furniture) take(f.model);
  return out;
}

}  // namespace demoplan
