#pragma once
// Can each pick of the demonstration be done at all? A pick moves one object from one placement
// to the next; it can be done when some handle of the object both grasps it at the first
// placement and releases it at the second collision-free (the handle cannot change while the
// object is held). Sampling the transitions answers it, with the reason when no handle does:
// a handle out of the arm's reach, or a hand that would sit inside the part.
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "core/graph/projector.h"
#include "core/scene/collision_checker.h"

namespace demoplan {

struct TransitionSampling {
  int samples = 0;
  int projected = 0;       // the gripper reached the handle and followed the approach axis
  int collision_free = 0;  // ... and both ends and the approach are collision-free
  std::map<std::string, int> failures;  // reason -> count
  // The most frequent reason with its count; a collision when the handle was ever reached.
  std::string main_failure() const;
};

struct PickFeasibility {
  int pick = -1;  // k: from placement_sequence[k] to placement_sequence[k + 1]
  int object = -1;
  std::vector<std::string> handles;  // handles whose grasp and release both sampled collision-free
  std::string reason;                // when none: per handle, the end that failed and why
  bool feasible() const { return !handles.empty(); }
};

struct FeasibilityReport {
  std::vector<TransitionSampling> transitions;  // by transition index
  std::vector<PickFeasibility> picks;
  double projection_seconds = 0.0;  // time spent in sample_on_transition
  bool feasible() const;
  // One line per pick that cannot be done; empty when every pick can.
  std::string summary(const Scene& scene) const;
};

// Samples every transition `samples` times from random seeds (deterministic for a seed).
FeasibilityReport assess_picks(const Scene& scene, const ConstraintGraph& graph, const CollisionChecker& checker,
                               int samples, std::uint64_t seed = 1);

}  // namespace demoplan
