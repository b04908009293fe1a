#include "core/planning/path_from_nodes.h"

namespace demoplan {

Path make_path(const Scene& scene, const ConstraintGraph& graph, const std::vector<Eigen::VectorXd>& qs,
               const std::vector<int>& states, const std::vector<char>& approach_to_next) {
  Path p;
  for (const Joint* j : scene.robot.model.configuration_joints()) p.joint_names.push_back(j->name);
  for (const auto& o : scene.objects) p.object_ids.push_back(o.id);
  for (size_t k = 0; k < qs.size(); ++k) {
    Waypoint w;
    w.q = qs[k];
    w.state = states[k];
    w.state_name = graph.states[states[k]].name;
    w.objects = scene_state(scene, graph, states[k], qs[k]).objects;
    w.approach = approach_to_next[k];
    const GraphState& s = graph.states[states[k]];
    // The gripper closes on entering a grasp state and opens on its last node before leaving.
    if (s.kind == StateKind::Grasp) {
      if (k > 0 && states[k - 1] != states[k]) w.action = GripperAction::Grasp, w.object = s.object;
      else if (k + 1 < qs.size() && states[k + 1] != states[k]) w.action = GripperAction::Release, w.object = s.object;
    }
    p.waypoints.push_back(std::move(w));
  }
  return p;
}

}  // namespace demoplan
