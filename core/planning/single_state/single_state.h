#pragma once
// Single-state motion problems: move the robot between two configurations of ONE state of a
// problem's constraint graph (every part resting, or one held with its grasp kept), as the
// transit and transfer pieces of a guided solution do. Solved by our RRT-Connect
// (connect_in_state.h) or, when demoplan is built with OMPL, by OMPL's planners on the same
// collision checking and edge resolution, so the two can be compared on equal terms.
#include <string>
#include <vector>

#include <Eigen/Core>

#include "core/planning/planning_problem.h"
#include "core/planning/stop_condition.h"

namespace demoplan {

struct SingleStateResult {
  bool solved = false;
  std::string message;                // why not, when not solved
  std::vector<Eigen::VectorXd> path;  // q_from ... q_to, joined by straight moves, when solved
  double time_s = 0.0;                // the search only (setup excluded, for both kinds)
  double length() const;              // joint-space length of `path`
};

// Our own planner's name; the OMPL ones start with "ompl-".
inline constexpr const char* kOurSingleStatePlanner = "rrtconnect";

// Whether this build has OMPL (DEMOPLAN_HAS_OMPL).
bool ompl_available();
// Every name solve_single_state accepts in this build.
std::vector<std::string> single_state_planner_names();
// The OMPL planner names, whether built in or not (to tell "not built" from "unknown").
std::vector<std::string> ompl_planner_names();

// Edges are collision-checked every `resolution` (PlannerParams::resolution). `q_from` and `q_to`
// must be collision-free in `state`. Throws InputError for an unknown planner, or an ompl-* one
// in a build without OMPL. Reproducible for a given seed unless `stop` ends the search.
SingleStateResult solve_single_state(const PlanningProblem& problem, int state, const Eigen::VectorXd& q_from,
                                     const Eigen::VectorXd& q_to, const std::string& planner,
                                     const StopCondition& stop, std::uint64_t seed, double resolution = 0.005);

}  // namespace demoplan
