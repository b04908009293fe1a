#pragma once
// The yardstick for the time parameterization: each segment of the path on its own, stopping at
// every waypoint, with the fastest synchronized trapezoidal velocity profile (no jerk limit).
#include "core/path/path.h"
#include "core/trajectory/joint_limits.h"

namespace demoplan {

// Total duration in s.
double trapezoid_duration(const Path& path, const JointLimitSet& limits);

}  // namespace demoplan
