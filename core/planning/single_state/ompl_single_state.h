#pragma once
// OMPL's planners on a single-state problem (built only with OMPL; single_state.h is the
// interface). Joint space as a RealVectorStateSpace within the robot's joint limits (the gripper
// held open in a grasp state, as our sampler does), our collision checking as the state validity
// checker (one CollisionData per thread) and our edge check at `resolution` as the motion
// validator: the same checks our RRT-Connect makes.
#include <string>
#include <vector>

#include "core/planning/single_state/single_state.h"

namespace demoplan {

// `planner` must be one of ompl_planner_names(); OMPL's seed is process-wide, so calls
// are serialized.
SingleStateResult solve_single_state_ompl(const PlanningProblem& problem, int state, const Eigen::VectorXd& q_from,
                                          const Eigen::VectorXd& q_to, const std::string& planner,
                                          const StopCondition& stop, std::uint64_t seed, double resolution);

}  // namespace demoplan
