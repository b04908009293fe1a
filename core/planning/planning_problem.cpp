#include "core/planning/planning_problem.h"

namespace demoplan {

PlanningProblem make_planning_problem(std::shared_ptr<const Scene> scene, const Demonstration& demo,
                                      ValidationTask validation) {
  PlanningProblem p;
  p.graph = std::make_shared<const ConstraintGraph>(build_constraint_graph(*scene, demo));
  p.demonstration = std::make_shared<const Demonstration>(demo);
  p.checker = std::make_shared<const CollisionChecker>(*scene);
  p.scene = std::move(scene);
  p.validation = std::move(validation);
  return p;
}

}  // namespace demoplan
