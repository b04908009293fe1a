#pragma once
// The limits a trajectory must respect, per configuration joint: positions and velocities from
// the URDF, accelerations and jerks from a per-robot default table (URDF has none), all
// overridable per call. See docs/trajectory.md for the table and where each number comes from.
#include <Eigen/Core>
#include <map>
#include <string>
#include <vector>

#include "core/model/robot_model.h"
#include "core/path/path.h"

namespace demoplan {

struct JointLimitSet {
  std::vector<std::string> names;  // configuration order
  Eigen::VectorXd lower, upper;    // rad or m
  Eigen::VectorXd velocity;        // rad/s or m/s: the URDF's, capped by the datasheet where known
  Eigen::VectorXd acceleration;    // rad/s^2 or m/s^2
  Eigen::VectorXd jerk;            // rad/s^3 or m/s^3
  // True where the jerk is the controller's own limit (Franka), false where it is our smoothing
  // default (the profile still respects it).
  std::vector<bool> jerk_published;
  std::vector<std::string> sources;  // per joint: where the acceleration and jerk come from

  long size() const { return velocity.size(); }
};

// Replaces table values for named joints, then scales. Every value must be finite and > 0;
// scales in (0, 1].
struct LimitOverrides {
  std::map<std::string, double> velocity, acceleration, jerk;
  double velocity_scale = 1.0;
  double acceleration_scale = 1.0;  // jerk scales with it
};

// Limits of `model`'s configuration joints. Throws InputError naming the URDF and the joint when
// a joint has no velocity limit (0 in the URDF) or no acceleration is known for it.
JointLimitSet trajectory_limits(const RobotModel& model, const LimitOverrides& overrides = {});

// Throws InputError("<source>", "waypoints[k].q[j]", ...) for a waypoint outside the position
// limits (beyond `tolerance`), and ("<source>", "joint_names", ...) when the path's joints are
// not the limits' joints.
void check_path_within_limits(const Path& path, const JointLimitSet& limits, const std::string& source,
                              double tolerance = 1e-9);

// One line per distinct limit group, for the header comment of an exported program.
std::vector<std::string> describe_limits(const JointLimitSet& limits, const std::vector<int>& joints);

}  // namespace demoplan
