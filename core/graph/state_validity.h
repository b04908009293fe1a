#pragma once
// Collision checks of configurations and straight joint-space moves within a graph state,
// with every pair checked as the benchmark does (no allowed contacts).
#include "core/graph/constraint_graph.h"
#include "core/graph/projector.h"
#include "core/scene/collision_checker.h"

namespace demoplan {

class StateValidity {
public:
  // `resolution`: largest joint-space step (Euclidean norm, rad or m) between checked samples.
  StateValidity(const Scene& scene, const ConstraintGraph& graph, const CollisionChecker& checker,
                double resolution = 0.02);

  bool configuration_free(int state, const Eigen::VectorXd& q, CollisionData& data,
                          CollisionPair* hit = nullptr) const;
  // Samples strictly between the ends (the ends are assumed checked already), in bisection
  // order: `hit` is the first collision found in that order, not the one nearest `a`.
  bool segment_free(int state, const Eigen::VectorXd& a, const Eigen::VectorXd& b,
                    CollisionData& data, CollisionPair* hit = nullptr) const;
  // Both ends in their states and the approach or retreat move in its placement state.
  bool transition_free(const TransitionSample& sample, CollisionData& data,
                       CollisionPair* hit = nullptr) const;

  double resolution() const { return resolution_; }

private:
  const Scene& scene_;
  const ConstraintGraph& graph_;
  const CollisionChecker& checker_;
  double resolution_;
};

}  // namespace demoplan
