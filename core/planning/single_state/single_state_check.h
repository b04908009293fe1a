#pragma once
// The independent check of a single-state path: every configuration collision-free in the state
// and every straight move between them sampled at the validator's step (0.01 rad), with no
// allowed contacts, whoever planned it.
#include <string>
#include <vector>

#include <Eigen/Core>

#include "core/planning/planning_problem.h"

namespace demoplan {

struct SingleStateCheck {
  bool valid = false;
  std::string message;  // the first failure: which configuration or edge, and what collides
};

SingleStateCheck check_single_state_path(const PlanningProblem& problem, int state,
                                         const std::vector<Eigen::VectorXd>& path, const Eigen::VectorXd& q_from,
                                         const Eigen::VectorXd& q_to, double step = 0.01);

}  // namespace demoplan
