#pragma once
// The multi-contact RRT guided by the demonstration (Alg. 1 and 2 of the paper): trees rooted
// at the start and goal configurations, more trees rooted at sampled transitions, each grown in
// its states and linked to the other trees of the same state until start and goal share a tree.
// What it adds to the paper is listed at PlannerParams.
#include "core/planning/planner.h"

namespace demoplan {

class GuidedPlanner final : public Planner {
public:
  explicit GuidedPlanner(const PlannerParams& params = {}) : params_(params) {}
  std::string name() const override { return "guided"; }
  // params.time_limit is not read here: `stop` carries the time limit.
  PlanResult solve(const PlanningProblem& problem, const StopCondition& stop,
                   const ProgressCallback& progress = {}) override;

private:
  PlannerParams params_;
};

}  // namespace demoplan
