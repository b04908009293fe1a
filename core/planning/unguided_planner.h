#pragma once
// A manipulation planner without the demonstration, as HPP's M-RRT searches (Mirabel et al.,
// reference [5] of the paper): it knows the start and goal placements of the parts only. Its
// placement states are discovered while it plans (a released part rests on any support, anywhere,
// turned about the normal: RestingPoseSampler), its grasp states are a part held by one of its
// handles with the others where they rest. Two trees, rooted at start and goal, grow towards a
// random configuration each iteration: from the nearest node, along an edge of its state chosen
// at random (move within the state, or grasp a part, or release the held one), the random
// configuration projected onto the edge's target state; new nodes are linked to the other tree
// in the same state. Same projector, collision checker, final check and shortcut as the guided
// planner. A task where two parts move needs a part released exactly where the other tree has
// it, which random placements never hit: the search the paper's Fig. 4 shows failing.
#include "core/planning/planner.h"

namespace demoplan {

struct UnguidedParams {
  // Probability of leaving the nearest node's state (grasp or release) instead of moving in it.
  double leave_state = 0.5;
  // Probability of releasing a part at its goal placement instead of a random one. 0 is HPP's
  // search; above 0 it is told where the goal is, a goal bias in RRT's sense.
  double goal_placement_bias = 0.0;
};

class UnguidedPlanner final : public Planner {
public:
  explicit UnguidedPlanner(const PlannerParams& params = {}, const UnguidedParams& unguided = {})
      : params_(params), unguided_(unguided) {}
  std::string name() const override { return "unguided"; }
  // The result's path indexes the states of result.graph (the planner's own), not the problem's.
  PlanResult solve(const PlanningProblem& problem, const StopCondition& stop,
                   const ProgressCallback& progress = {}) override;

private:
  PlannerParams params_;
  UnguidedParams unguided_;
};

}  // namespace demoplan
