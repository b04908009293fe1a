#pragma once
// What every planner solves: move the robot in `scene` from graph->q_start in
// graph->start_state to graph->q_goal in graph->goal_state through the states and transitions
// of the constraint graph, collision-checked by `checker`; a found path is judged by the
// independent validator against `validation`. Immutable once made: planners, the shortcut,
// the validator and the GUI share it across threads (as Pinocchio shares its Model).
#include <memory>

#include "core/demo/demonstration.h"
#include "core/graph/constraint_graph.h"
#include "core/scene/collision_checker.h"
#include "core/validation/path_validator.h"

namespace demoplan {

struct PlanningProblem {
  std::shared_ptr<const Scene> scene;
  std::shared_ptr<const ConstraintGraph> graph;
  std::shared_ptr<const CollisionChecker> checker;  // of *scene
  ValidationTask validation;
  // The demonstration the graph was built from; planners that change it (a regrasp) start here.
  std::shared_ptr<const Demonstration> demonstration;
};

// Builds the constraint graph of `demo` and a collision checker for `scene`. Throws InputError
// when the demonstration cannot be planned (naming the event).
PlanningProblem make_planning_problem(std::shared_ptr<const Scene> scene, const Demonstration& demo,
                                      ValidationTask validation);

}  // namespace demoplan
