#include "core/placement/base_placement.h"

#include <algorithm>
#include <chrono>

#include "core/error.h"
#include "core/graph/pick_feasibility.h"
#include "core/graph/state_validity.h"
#include "core/placement/base_clearance.h"
#include "core/planning/plan_job.h"
#include "core/trajectory/joint_limits.h"
#include "core/validation/trajectory_collisions.h"

namespace demoplan {

namespace {

constexpr double kNoClockLimit = 24 * 3600.0;  // s: longer than any candidate's shortcut

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

PlacementRun plan_once(const PlanningProblem& problem, const PlacementSettings& settings, std::uint64_t seed,
                       const std::atomic<bool>* cancel) {
  PlannerSettings s = settings.planner;
  s.planner.seed = seed;
  s.shortcut = true;
  // A candidate's cycle time must be the same loaded, in a shard and alone: the shortcut ends by
  // its failure count and the put-back detours by their rounds, never by the clock (a long
  // shelf_1 path shortens for 6.7 s idle, and three busy loops on 2 cores cut it at 10 s).
  s.shortcutting.time_limit = kNoClockLimit;
  s.shortcutting.detour_time = kNoClockLimit;
  const PlanReport report = run_plan_job(problem, s, {}, cancel, {.assess_on_failure = false,
                                                                  .validate_planner_path = false});
  PlacementRun run;
  run.seed = seed;
  run.planning_time_s = report.plan.planning_time_s;
  if (!report.solved()) {
    run.message = report.plan.message.empty() ? "not solved" : report.plan.message;
    return run;
  }
  if (!report.valid()) {
    run.message = "invalid: " + report.validation.message;
    return run;
  }
  // The cycle: the trajectory the exported program would run (rests added where a blend touches).
  // A path the timing refuses (a robot without velocity limits) is no program: said, not thrown
  // out of a worker thread.
  try {
    const JointLimitSet limits = trajectory_limits(problem.scene->robot.model);
    run.cycle_time_s = time_parameterize_clear(*problem.scene, *problem.checker, report.path, limits, {}).trajectory.duration;
  } catch (const std::exception& e) {
    run.message = std::string("cannot be timed: ") + e.what();
    return run;
  }
  run.valid = true;
  run.path_length = report.validation.length.robot;
  run.grasps = report.validation.grasps;
  return run;
}

}  // namespace

std::string screen_candidate(const PlanningProblem& problem, int samples) {
  const Scene& scene = *problem.scene;
  if (std::string base = base_clearance(scene); !base.empty()) return base;
  const ConstraintGraph& graph = *problem.graph;
  const StateValidity validity(scene, graph, *problem.checker);
  CollisionData data = problem.checker->make_data();
  CollisionPair hit;
  if (!validity.configuration_free(graph.start_state, graph.q_start, data, &hit))
    return "the start configuration collides: " + hit.first + " / " + hit.second;
  if (!validity.configuration_free(graph.goal_state, graph.q_goal, data, &hit))
    return "the goal configuration collides: " + hit.first + " / " + hit.second;
  const FeasibilityReport f = assess_picks(scene, graph, *problem.checker, samples, 1);
  if (f.feasible()) return "";
  std::string summary = f.summary(scene);
  const size_t end = summary.find('\n');
  return end == std::string::npos ? summary : summary.substr(0, end);
}

PlacementCandidate evaluate_candidate(const ProblemAtBase& problem_at, int index, const BasePose& base,
                                      const PlacementSettings& settings, const std::atomic<bool>* cancel) {
  PlacementCandidate c;
  c.index = index;
  c.base = base;
  if (cancel && cancel->load()) return c;
  const auto t0 = std::chrono::steady_clock::now();
  PlanningProblem problem;
  try {
    problem = problem_at(base.pose());
    c.reason = screen_candidate(problem, settings.screen_samples);
  } catch (const InputError& e) {
    c.reason = e.reason();
  } catch (const std::exception& e) {  // never out of a worker thread
    c.reason = e.what();
  }
  c.screened = true;
  c.feasible = c.reason.empty();
  c.screen_time_s = seconds_since(t0);
  if (!problem.graph || (!c.feasible && !settings.plan_rejected)) return c;
  for (std::uint64_t seed : settings.seeds) {
    if (cancel && cancel->load()) break;
    c.runs.push_back(plan_once(problem, settings, seed, cancel));
  }
  return c;
}

}  // namespace demoplan
