#pragma once
// A planner's node sequence as a Path: object poses from each node's state, gripper actions
// where the state changes between a placement and a grasp.
#include <vector>

#include "core/graph/constraint_graph.h"
#include "core/path/path.h"

namespace demoplan {

Path make_path(const Scene& scene, const ConstraintGraph& graph, const std::vector<Eigen::VectorXd>& qs,
               const std::vector<int>& states, const std::vector<char>& approach_to_next);

}  // namespace demoplan
