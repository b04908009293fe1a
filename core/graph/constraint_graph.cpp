#include "core/graph/constraint_graph.h"

#include "core/error.h"
#include "core/model/kinematics.h"

namespace demoplan {

std::vector<int> ConstraintGraph::states_of_kind(StateKind kind) const {
  std::vector<int> out;
  for (size_t i = 0; i < states.size(); ++i)
    if (states[i].kind == kind) out.push_back(static_cast<int>(i));
  return out;
}

Pose gripper_link_T_object(const Scene& scene, int object, int handle) {
  const auto& h = scene.objects[object].srdf.handles[handle];
  // Handles of single-link objects are in the object frame (the benchmark's objects are).
  return scene.robot.gripper().pose * h.pose.inverse();
}

bool same_placements(const std::vector<ObjectPlacement>& a, const std::vector<ObjectPlacement>& b,
                     const GraphOptions& o) {
  for (size_t i = 0; i < a.size(); ++i) {
    if (a[i].link != b[i].link) return false;
    const Pose d = a[i].pose.inverse() * b[i].pose;
    if (d.translation().norm() > o.same_position || log3(d.linear()).norm() > o.same_rotation) return false;
  }
  return true;
}

namespace {

// Movable joints in the subtree of the gripper link: the fingers.
std::vector<int> gripper_joint_slots(const RobotModel& m, int gripper_link) {
  std::vector<int> slots, stack{gripper_link};
  while (!stack.empty()) {
    const int l = stack.back();
    stack.pop_back();
    for (int j : m.links[l].child_joints) {
      if (m.joints[j].q_index >= 0) slots.push_back(m.joints[j].q_index);
      stack.push_back(m.joints[j].child_link);
    }
  }
  std::sort(slots.begin(), slots.end());
  return slots;
}

}  // namespace

ConstraintGraph build_constraint_graph(const Scene& scene, const Demonstration& demo,
                                       const GraphOptions& options) {
  const std::string source = "demonstration of " + (demo.task.empty() ? scene.name : demo.task);
  if (auto issues = validate(demo); !issues.empty()) {
    const auto& i = issues.front();
    throw InputError(source, i.event >= 0 ? "events[" + std::to_string(i.event) + "]" : "", i.message);
  }
  const size_t n = scene.objects.size();
  if (demo.object_ids.size() != n) throw InputError(source, "objects", "must list the scene's objects");
  for (size_t o = 0; o < n; ++o)
    if (demo.object_ids[o] != scene.objects[o].id)
      throw InputError(source, "objects[" + std::to_string(o) + "]",
                       "is '" + demo.object_ids[o] + "', the scene has '" + scene.objects[o].id + "'");

  ConstraintGraph g;
  const RobotModel& model = scene.robot.model;
  auto placement_of = [&](const ContactEvent& e, int o) {
    ObjectPlacement p{-1, e.poses[o]};
    if (const std::string& frame = e.pose_frame(o); !frame.empty()) {
      p.link = model.link_index(frame);
      if (p.link < 0)
        throw InputError(source, "events: pose_frames." + scene.objects[o].id,
                         "'" + frame + "' is not a link of " + scene.robot.name);
    }
    return p;
  };
  g.gripper_joints = gripper_joint_slots(model, scene.robot.gripper_link);
  for (int i = 0; i < model.nq; ++i)
    if (std::find(g.gripper_joints.begin(), g.gripper_joints.end(), i) == g.gripper_joints.end())
      g.reach_joints.push_back(i);
  g.gripper_open.resize(static_cast<long>(g.gripper_joints.size()));
  for (size_t k = 0; k < g.gripper_joints.size(); ++k) g.gripper_open[static_cast<long>(k)] = model.upper_limits()[g.gripper_joints[k]];

  // Each object rests where it was first grasped (or, never moved, where the first event sees
  // it) until it is released somewhere else.
  std::vector<ObjectPlacement> resting(n);
  for (size_t o = 0; o < n; ++o) {
    const ContactEvent* first = &demo.events.front();
    for (const auto& e : demo.events)
      if (e.object == static_cast<int>(o) && e.type == EventType::Grasp) {
        first = &e;
        break;
      }
    resting[o] = placement_of(*first, static_cast<int>(o));
  }
  auto add_placement = [&](const std::vector<ObjectPlacement>& placements, int step) {
    for (int s : g.placement_sequence)
      if (same_placements(g.states[s].objects, placements, options)) return s;
    GraphState p;
    p.kind = StateKind::Placement;
    p.name = "P" + std::to_string(g.placement_sequence.size());
    p.objects = placements;
    p.step = step;
    g.states.push_back(std::move(p));
    g.placement_sequence.push_back(static_cast<int>(g.states.size()) - 1);
    return static_cast<int>(g.states.size()) - 1;
  };

  int current = add_placement(resting, 0);
  g.start_state = current;
  const double opening = scene.robot.gripper().clearance;
  int pick = 0;
  for (size_t i = 0; i < demo.events.size(); ++i) {
    const ContactEvent& grasp = demo.events[i];
    if (grasp.type != EventType::Grasp) continue;
    // validate() guarantees that the next event is this object's release (one at a time).
    const ContactEvent& release = demo.events[i + 1];
    const int o = grasp.object;
    std::vector<ObjectPlacement> after = g.states[current].objects;
    after[o] = placement_of(release, o);
    const int next = add_placement(after, pick + 1);
    const auto& handles = scene.objects[o].srdf.handles;
    GraphPick gp;
    gp.object = o;
    gp.from = current;
    gp.to = next;
    for (size_t h = 0; h < handles.size(); ++h) {
      if (handles[h].clearance > opening) continue;  // wider than the gripper opens
      GraphState gs;
      gs.kind = StateKind::Grasp;
      gs.name = "G" + std::to_string(pick) + " " + scene.objects[o].id + "/" + handles[h].name;
      gs.objects = g.states[current].objects;
      gs.object = o;
      gs.handle = static_cast<int>(h);
      gs.step = pick;
      g.states.push_back(std::move(gs));
      const int gi = static_cast<int>(g.states.size()) - 1;
      g.transitions.push_back({TransitionKind::Grasp, current, gi, o, static_cast<int>(h),
                               g.states[current].name + " -> " + g.states[gi].name});
      g.transitions.push_back({TransitionKind::Release, gi, next, o, static_cast<int>(h),
                               g.states[gi].name + " -> " + g.states[next].name});
      gp.grasp_states.push_back(gi);
      gp.grasp.push_back(static_cast<int>(g.transitions.size()) - 2);
      gp.release.push_back(static_cast<int>(g.transitions.size()) - 1);
    }
    if (gp.grasp_states.empty())
      throw InputError(source, "events[" + std::to_string(i) + "]",
                       scene.objects[o].id + " has no handle the gripper can open around (clearance <= " +
                           std::to_string(opening) + " m)");
    g.picks.push_back(std::move(gp));
    current = next;
    ++pick;
  }
  g.goal_state = current;
  g.q_start = g.q_goal = scene.robot.initial_configuration;
  return g;
}

SceneState scene_state(const Scene& scene, const ConstraintGraph& graph, int state,
                       const Eigen::VectorXd& q) {
  const GraphState& s = graph.states[state];
  SceneState out;
  out.q = q;
  for (size_t o = 0; o < s.objects.size(); ++o) {
    const auto& p = s.objects[o];
    out.objects.push_back(p.pose);
    if (s.kind == StateKind::Grasp && s.object == static_cast<int>(o))
      out.attachments.push_back({static_cast<int>(o), scene.robot.gripper_link,
                                 gripper_link_T_object(scene, s.object, s.handle)});
    else if (p.link >= 0)
      out.attachments.push_back({static_cast<int>(o), p.link, p.pose});
  }
  if (!out.attachments.empty()) {
    PoseVector links;
    forward_kinematics(scene.robot.model, q, scene.robot.base, links);
    update_attached_objects(links, out);
  }
  return out;
}

}  // namespace demoplan
