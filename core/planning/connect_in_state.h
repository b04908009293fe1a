#pragma once
// RRT-Connect between two configurations of one graph state: used to join the two ends of a
// detour the guided planner left in a path (shortcut.h). Small, short-lived trees: nearest
// neighbours by linear scan.
#include <chrono>
#include <optional>
#include <random>
#include <vector>

#include "core/graph/state_validity.h"

namespace demoplan {

struct ConnectParams {
  double step = 0.3;  // rad: extension step, as the guided planner's delta
  // Try the straight move a-b before growing trees: right for joining the ends of a put-back
  // detour, where it is often free; wasted where the caller knows it is blocked.
  bool straight_first = true;
  std::chrono::steady_clock::time_point deadline;
  // Rounds of growing (a sample, then the other tree toward it) before giving up: a bound that
  // does not depend on the machine's load, so a run that gives up does so on every machine.
  long max_rounds = 1000;
};

// The configurations strictly between `a` and `b` of a collision-free piecewise-straight path
// in `state` (empty when the straight segment is free), or nothing after max_rounds or by the deadline.
// Both ends must be collision-free. Deterministic for a given rng state (as long as the deadline
// is not what stops it).
std::optional<std::vector<Eigen::VectorXd>> connect_in_state(const ConstraintProjector& sampler,
                                                              const StateValidity& validity, CollisionData& data,
                                                              int state, const Eigen::VectorXd& a,
                                                              const Eigen::VectorXd& b, std::mt19937_64& rng,
                                                              const ConnectParams& params);

}  // namespace demoplan
