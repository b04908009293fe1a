#pragma once
// A timed motion of the robot along a planned path: the continuous motion, when each path
// waypoint is reached, where the robot rests, and the gripper state over time.
#include <string>
#include <vector>

#include "core/path/path.h"
#include "core/trajectory/motion.h"

namespace demoplan {

struct TrajectorySample {
  double t = 0;  // s from the start
  Eigen::VectorXd q, v, a;
  bool gripper_closed = false;
};

struct Trajectory {
  std::vector<std::string> joint_names;  // configuration order
  Motion motion;                         // from t = 0 to duration
  std::vector<double> waypoint_times;    // when each path waypoint is reached
  std::vector<char> stops;               // per waypoint: the robot is at rest there
  std::vector<GripperAction> actions;    // per waypoint, as in the path
  bool starts_closed = false;            // the path starts holding an object
  double duration = 0;                   // s
  double trapezoid_duration = 0;         // s: per-segment trapezoids stopping at every waypoint
  double safety_scale = 1;               // > 1 when the final check had to slow the motion down
  // Where the motion leaves the path's straight segments: the blend around a pass-through
  // waypoint, from `begin` to `end` (s). Everywhere else it is on the path.
  struct Blend {
    size_t waypoint = 0;
    double begin = 0, end = 0;
  };
  std::vector<Blend> blends;

  // Closed from a grasp waypoint's time until the next release waypoint's time.
  bool gripper_closed_at(double t) const;
  TrajectorySample sample_at(double t) const;
  // Samples every 1/rate s from 0, the end, and, with include_waypoints, each waypoint's exact
  // time (so every waypoint is a sample), in time order without repeats.
  std::vector<TrajectorySample> sample(double rate, bool include_waypoints = true) const;
};

}  // namespace demoplan
