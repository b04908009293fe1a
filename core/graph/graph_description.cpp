#include "core/graph/graph_description.h"

#include <cmath>
#include <sstream>

namespace demoplan {

namespace {

std::string pose_text(const Pose& T) {
  const Eigen::Matrix3d& R = T.linear();
  // URDF rpy from R = Rz(yaw) Ry(pitch) Rx(roll).
  const double pitch = std::asin(std::clamp(-R(2, 0), -1.0, 1.0));
  const double roll = std::atan2(R(2, 1), R(2, 2)), yaw = std::atan2(R(1, 0), R(0, 0));
  std::ostringstream s;
  s.setf(std::ios::fixed);
  s.precision(3);
  s << "xyz (" << T.translation().x() << ", " << T.translation().y() << ", " << T.translation().z() << ") m";
  s.precision(1);
  s << ", rpy (" << roll * 180 / M_PI << ", " << pitch * 180 / M_PI << ", " << yaw * 180 / M_PI << ") deg";
  return s.str();
}

std::vector<std::string> constraints(const Scene& scene, const ConstraintGraph& g, const GraphState& s) {
  std::vector<std::string> out;
  for (size_t o = 0; o < s.objects.size(); ++o) {
    const std::string& id = scene.objects[o].id;
    if (s.kind == StateKind::Grasp && s.object == static_cast<int>(o)) {
      const auto& h = scene.objects[o].srdf.handles[s.handle];
      out.push_back(id + " is held: gripper frame on handle " + h.name + " (clearance " +
                    std::to_string(h.clearance) + " m)");
      continue;
    }
    const auto& p = s.objects[o];
    if (p.link >= 0)
      out.push_back(id + " rests on the robot's " + scene.robot.model.links[p.link].name + " at " + pose_text(p.pose));
    else
      out.push_back(id + " rests at " + pose_text(p.pose));
  }
  if (s.kind == StateKind::Grasp) out.push_back("gripper joints held open");
  else out.push_back("robot free within its joint limits");
  (void)g;
  return out;
}

}  // namespace

nlohmann::json describe_graph(const Scene& scene, const ConstraintGraph& g) {
  nlohmann::json states = nlohmann::json::array(), transitions = nlohmann::json::array();
  for (const auto& s : g.states)
    states.push_back({{"name", s.name},
                      {"kind", s.kind == StateKind::Placement ? "placement" : "grasp"},
                      {"constraints", constraints(scene, g, s)}});
  for (const auto& t : g.transitions)
    transitions.push_back({{"name", t.name},
                           {"kind", t.kind == TransitionKind::Grasp ? "grasp" : "release"},
                           {"from", g.states[t.from].name},
                           {"to", g.states[t.to].name},
                           {"object", scene.objects[t.object].id},
                           {"handle", scene.objects[t.object].srdf.handles[t.handle].name},
                           {"approach_state", g.states[t.edge_state()].name}});
  return {{"states", states},
          {"transitions", transitions},
          {"start", g.states[g.start_state].name},
          {"goal", g.states[g.goal_state].name}};
}

std::string describe_graph_text(const Scene& scene, const ConstraintGraph& g) {
  std::ostringstream s;
  s << "states (" << g.states.size() << "), start " << g.states[g.start_state].name << ", goal "
    << g.states[g.goal_state].name << "\n";
  for (const auto& st : g.states) {
    s << "  " << st.name << "\n";
    for (const auto& c : constraints(scene, g, st)) s << "      " << c << "\n";
  }
  s << "transitions (" << g.transitions.size() << ")\n";
  for (const auto& t : g.transitions)
    s << "  " << (t.kind == TransitionKind::Grasp ? "grasp   " : "release ") << t.name << "\n";
  return s.str();
}

nlohmann::json describe_picks(const Scene& scene, const FeasibilityReport& report) {
  nlohmann::json picks = nlohmann::json::array();
  for (const auto& p : report.picks)
    picks.push_back({{"pick", p.pick + 1},
                     {"object", scene.objects[p.object].id},
                     {"feasible", p.feasible()},
                     {"handles", p.handles},
                     {"reason", p.reason}});
  return picks;
}

}  // namespace demoplan
