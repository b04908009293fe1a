#include "core/planning/single_state/single_state.h"

#include <algorithm>
#include <chrono>
#include <random>

#include "core/error.h"
#include "core/graph/state_validity.h"
#include "core/planning/connect_in_state.h"
#ifdef DEMOPLAN_HAS_OMPL
#include "core/planning/single_state/ompl_single_state.h"
#endif

namespace demoplan {

double SingleStateResult::length() const {
  double l = 0.0;
  for (size_t k = 1; k < path.size(); ++k) l += (path[k] - path[k - 1]).norm();
  return l;
}

bool ompl_available() {
#ifdef DEMOPLAN_HAS_OMPL
  return true;
#else
  return false;
#endif
}

std::vector<std::string> ompl_planner_names() {
  return {"ompl-rrtconnect", "ompl-prm", "ompl-kpiece", "ompl-bitstar"};
}

std::vector<std::string> single_state_planner_names() {
  std::vector<std::string> out{kOurSingleStatePlanner};
  if (ompl_available())
    for (const auto& n : ompl_planner_names()) out.push_back(n);
  return out;
}

namespace {

SingleStateResult solve_ours(const PlanningProblem& problem, int state, const Eigen::VectorXd& q_from,
                             const Eigen::VectorXd& q_to, const StopCondition& stop, std::uint64_t seed,
                             double resolution) {
  const ConstraintProjector sampler(*problem.scene, *problem.graph);
  const StateValidity validity(*problem.scene, *problem.graph, *problem.checker, resolution);
  CollisionData data = problem.checker->make_data();
  SingleStateResult out;
  if (!validity.configuration_free(state, q_from, data) || !validity.configuration_free(state, q_to, data)) {
    out.message = "an end of the motion is in collision";
    return out;
  }
  std::mt19937_64 rng(seed);
  ConnectParams params;  // its step is the guided planner's delta, as OMPL's range is set to
  params.straight_first = false;  // plain RRT-Connect, as OMPL's: the trees find a free straight move
  // connect_in_state polls a deadline, not the StopCondition: the same limit from now.
  const double limit = std::min(stop.time_limit_s(), 1e6);
  const auto t0 = std::chrono::steady_clock::now();
  params.deadline = t0 + std::chrono::duration_cast<std::chrono::steady_clock::duration>(std::chrono::duration<double>(limit));
  const auto via = connect_in_state(sampler, validity, data, state, q_from, q_to, rng, params);
  out.time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (!via) {
    out.message = "no path within the time limit";
    return out;
  }
  out.path.push_back(q_from);
  out.path.insert(out.path.end(), via->begin(), via->end());
  out.path.push_back(q_to);
  out.solved = true;
  return out;
}

}  // namespace

SingleStateResult solve_single_state(const PlanningProblem& problem, int state, const Eigen::VectorXd& q_from,
                                     const Eigen::VectorXd& q_to, const std::string& planner,
                                     const StopCondition& stop, std::uint64_t seed, double resolution) {
  if (state < 0 || state >= static_cast<int>(problem.graph->states.size()))
    throw InputError("single-state problem", "state", std::to_string(state) + " is not a state of the graph");
  if (planner == kOurSingleStatePlanner) return solve_ours(problem, state, q_from, q_to, stop, seed, resolution);
  const auto ompl = ompl_planner_names();
  if (std::find(ompl.begin(), ompl.end(), planner) != ompl.end()) {
#ifdef DEMOPLAN_HAS_OMPL
    return solve_single_state_ompl(problem, state, q_from, q_to, planner, stop, seed, resolution);
#else
    throw InputError("planner", planner, "this demoplan was built without OMPL (install libompl-dev and rebuild)");
#endif
  }
  std::string known;
  for (const auto& n : single_state_planner_names()) known += (known.empty() ? "" : ", ") + n;
  throw InputError("planner", planner, "unknown single-state planner (known: " + known + ")");
}

}  // namespace demoplan
