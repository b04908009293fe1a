#pragma once
// A path through real configurations of a benchmark scene, for exercising the time
// parameterization and the exporters: the start, then for every pick of the demonstration a
// sampled grasp transition (pre-grasp, the straight approach, the grasp) and release transition
// (the release, the straight retreat), then the goal. Each transition is solved by the
// constraint projector from the previous configuration. It is not collision-free.
#include <random>
#include <stdexcept>
#include <string>

#include "core/demo/benchmark_demonstration.h"
#include "core/placement/deck_placement.h"
#include "core/demo/benchmark_scene.h"
#include "core/graph/constraint_graph.h"
#include "core/graph/projector.h"
#include "core/path/path.h"

namespace demoplan::testing_support {

struct BenchmarkPathCase {
  BenchmarkTask task;
  Scene scene;
  ConstraintGraph graph;
  Path path;
};

inline TransitionSample sample_transition(const ConstraintProjector& projector, int transition,
                                          const Eigen::VectorXd& seed, std::mt19937_64& rng) {
  for (int attempt = 0; attempt < 200; ++attempt) {
    TransitionSample s = attempt < 20 ? projector.sample_on_transition(transition, seed, rng)
                                      : projector.sample_on_transition(transition, rng);
    if (s.ok) return s;
  }
  return {};
}

inline BenchmarkPathCase benchmark_transition_path(const std::string& data_dir, const std::string& task_name,
                                                   const std::string& robot, std::uint64_t seed = 1) {
  BenchmarkPathCase c;
  c.task = load_benchmark_task(data_dir, task_name);
  const std::vector<int> poses = benchmark_pose_ids(c.task, robot);
  if (poses.empty()) throw std::runtime_error(task_name + " has no pose for " + robot);
  c.scene = build_benchmark_scene(c.task, robot, poses.front());
  c.graph = build_constraint_graph(
      c.scene, place_on_deck(c.scene, demonstration_from_benchmark(c.task, c.scene, PoseSource::Subgoals)).demonstration);
  const ConstraintGraph& g = c.graph;
  const ConstraintProjector projector(c.scene, g);
  std::mt19937_64 rng(seed);

  Path& p = c.path;
  p.task = task_name;
  p.robot = robot;
  p.robot_pose = poses.front();
  for (const Joint* j : c.scene.robot.model.configuration_joints()) p.joint_names.push_back(j->name);
  for (const auto& o : c.scene.objects) p.object_ids.push_back(o.id);
  auto add = [&](const Eigen::VectorXd& q, int state, GripperAction action, int object, bool approach) {
    Waypoint w;
    w.q = q;
    w.state = state;
    w.state_name = g.states[state].name;
    w.objects = scene_state(c.scene, g, state, q).objects;
    w.action = action;
    w.object = action == GripperAction::None ? -1 : object;
    w.approach = approach;
    p.waypoints.push_back(std::move(w));
  };

  add(g.q_start, g.start_state, GripperAction::None, -1, false);
  for (size_t k = 0; k + 1 < g.placement_sequence.size(); ++k) {
    const int from = g.placement_sequence[k], to = g.placement_sequence[k + 1];
    bool done = false;
    for (size_t ti = 0; ti < g.transitions.size() && !done; ++ti) {
      const GraphTransition& grasp = g.transitions[ti];
      if (grasp.kind != TransitionKind::Grasp || grasp.from != from) continue;
      int release = -1;
      for (size_t ri = 0; ri < g.transitions.size(); ++ri)
        if (g.transitions[ri].kind == TransitionKind::Release && g.transitions[ri].from == grasp.to &&
            g.transitions[ri].to == to)
          release = static_cast<int>(ri);
      if (release < 0) continue;
      const TransitionSample gs = sample_transition(projector, static_cast<int>(ti), p.waypoints.back().q, rng);
      if (!gs.ok) continue;
      const TransitionSample rs = sample_transition(projector, release, gs.q_to(), rng);
      if (!rs.ok) continue;
      for (size_t i = 0; i + 1 < gs.path.size(); ++i) add(gs.path[i], from, GripperAction::None, -1, true);
      add(gs.q_to(), grasp.to, GripperAction::Grasp, grasp.object, false);
      add(rs.path[0], grasp.to, GripperAction::Release, grasp.object, true);
      for (size_t i = 1; i < rs.path.size(); ++i) add(rs.path[i], to, GripperAction::None, -1, i + 1 < rs.path.size());
      done = true;
    }
    if (!done) throw std::runtime_error(task_name + " " + robot + ": no transition sample for pick " + std::to_string(k));
  }
  add(g.q_goal, g.goal_state, GripperAction::None, -1, false);
  return c;
}

}  // namespace demoplan::testing_support
