#pragma once
// An independent check of a sampled trajectory against the robot's limits and the planner's
// path. It trusts nothing from the time parameterization: only the samples, the path and the
// limits. Jerk is checked from the change of acceleration between samples (a mean jerk, so a
// valid trajectory never fails it); stored velocities and accelerations must agree with the
// positions (trapezoid rule within what the jerk limit allows), so they cannot hide a jump.
#include <string>
#include <vector>

#include "core/path/path.h"
#include "core/trajectory/joint_limits.h"
#include "core/trajectory/trajectory.h"

namespace demoplan {

struct CheckOptions {
  double waypoint_tolerance = 1e-6;  // rad or m, per joint
  double rest_tolerance = 1e-9;      // |velocity| at a stop
  double relative_tolerance = 1e-9;  // on every limit
  bool check_jerk = true;
  size_t max_violations = 20;        // messages kept
};

struct CheckReport {
  bool ok = true;
  std::vector<std::string> violations;  // first few, one line each
  std::vector<long> waypoint_samples;   // sample index where each waypoint is reached, -1 if never
  double peak_velocity_ratio = 0, peak_acceleration_ratio = 0, peak_jerk_ratio = 0;
  // Largest joint-space distance of a sample from the straight segment between the two waypoints
  // it lies between (blends leave the segments near pass-through waypoints).
  double max_path_deviation = 0;
};

CheckReport check_trajectory(const std::vector<TrajectorySample>& samples, const Path& path,
                             const JointLimitSet& limits, const CheckOptions& options = {});

}  // namespace demoplan
