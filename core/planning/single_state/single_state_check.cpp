#include "core/planning/single_state/single_state_check.h"

#include <sstream>

#include "core/graph/state_validity.h"

namespace demoplan {

SingleStateCheck check_single_state_path(const PlanningProblem& problem, int state,
                                         const std::vector<Eigen::VectorXd>& path, const Eigen::VectorXd& q_from,
                                         const Eigen::VectorXd& q_to, double step) {
  SingleStateCheck out;
  if (path.size() < 2) return {false, "the path has fewer than two configurations"};
  // A path that does not join the asked ends solves another problem.
  if ((path.front() - q_from).norm() > 1e-9 || (path.back() - q_to).norm() > 1e-9)
    return {false, "the path does not start at q_from and end at q_to"};
  const StateValidity validity(*problem.scene, *problem.graph, *problem.checker, step);
  CollisionData data = problem.checker->make_data();
  CollisionPair hit;
  for (size_t k = 0; k < path.size(); ++k) {
    if (path[k].size() != q_from.size()) return {false, "configuration " + std::to_string(k) + " has the wrong size"};
    if (!validity.configuration_free(state, path[k], data, &hit))
      return {false, "configuration " + std::to_string(k) + " collides: " + hit.first + " / " + hit.second};
    if (k > 0 && !validity.segment_free(state, path[k - 1], path[k], data, &hit))
      return {false, "edge " + std::to_string(k - 1) + "-" + std::to_string(k) + " collides: " + hit.first + " / " +
                         hit.second};
  }
  out.valid = true;
  return out;
}

}  // namespace demoplan
