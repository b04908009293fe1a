#pragma once
// The timed trajectory leaves the validated path only in its blends, where it cuts corners by
// up to a few hundredths of a radian; near a shelf or a table that can touch. This checks the
// trajectory itself against the scene, with the parts carried as along the path, and retimes
// it to rest at the corners whose blends collide (resting there follows the path exactly).
#include "core/path/path.h"
#include "core/scene/collision_checker.h"
#include "core/trajectory/time_parameterization.h"

namespace demoplan {

struct TrajectoryCollision {
  bool free = true;
  double time = 0;      // s: the first sample in collision
  size_t waypoint = 0;  // the waypoint of the blend it is in
  CollisionPair pair;
};

// Samples the blends of the trajectory so that consecutive configurations are at most
// `resolution` apart (joint-space norm) and checks each; the first collision, if any. Outside
// the blends the trajectory is on the path, which is the validator's to judge.
TrajectoryCollision first_trajectory_collision(const Scene& scene, const CollisionChecker& checker, const Path& path,
                                               const Trajectory& trajectory, double resolution = 0.005);

struct ClearTrajectory {
  Trajectory trajectory;
  std::vector<size_t> rests_added;  // waypoints where a colliding blend became a rest
};

// time_parameterize, then as long as a blend collides, rest at its waypoint instead (the robot
// then follows the path exactly there).
ClearTrajectory time_parameterize_clear(const Scene& scene, const CollisionChecker& checker, const Path& path,
                                        const JointLimitSet& limits, TimingOptions options = {});

}  // namespace demoplan
