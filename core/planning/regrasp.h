#pragma once
// Regrasps the demonstration does not show. Some picks cannot be done holding the part one way
// all along: a UR arm, say, grasps the part at its start only on one shoulder branch and
// releases it at its goal only on the other, and no motion holding the part crosses between
// them. Putting the part down where the hand can take it again (on any support, as the unguided
// planner's placements) splits such a pick in two, and the guided planner can plan both halves.
#include <functional>
#include <random>
#include <string>
#include <vector>

#include "core/demo/demonstration.h"
#include "core/planning/stop_condition.h"
#include "core/scene/collision_checker.h"

namespace demoplan {

struct Regrasp {
  int pick = -1;                   // k: the k-th grasp of the original demonstration
  int object = -1;
  Pose placement = Pose::Identity();  // world pose where the part is put down and taken again
};

// The demonstration with pick r.pick split: the part released at r.placement and grasped again
// there, every other part where it is during that pick. Throws InputError when there is no such
// pick.
Demonstration with_regrasp(const Demonstration& demo, const Regrasp& r);

// Up to `count` regrasps for pick `pick`: resting poses of its part on the scene's supports
// (RestingPoseSampler, at most `attempts` draws) where some handle that grasps the part at the
// pick's start releases it collision-free, and some handle grasps it again and releases it at
// the pick's goal (each transition sampled up to `samples` times). Deterministic for `rng`.
// `tick` runs after every transition sample (a planner reports its progress there).
std::vector<Regrasp> find_regrasps(const Scene& scene, const Demonstration& demo, const CollisionChecker& checker,
                                   int pick, int count, std::mt19937_64& rng, const StopCondition& stop,
                                   int attempts = 200, int samples = 8, const std::function<void()>& tick = {});

// "pick 2 (YCBV_03): put down at (0.31, -0.12, 0.80) m and taken again"
std::string describe(const Scene& scene, const Regrasp& r);

}  // namespace demoplan
