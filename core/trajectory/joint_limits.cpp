#include "core/trajectory/joint_limits.h"

#include <cmath>
#include <cstdio>
#include <limits>

#include "core/error.h"

namespace demoplan {

namespace {

constexpr double kDeg = M_PI / 180.0;
constexpr double kNone = std::numeric_limits<double>::infinity();

// One row of the default table. velocity_cap: the datasheet's maximum when it is below the URDF
// value (kNone: the URDF value stands).
struct TableRow {
  const char* joint;
  double velocity_cap, acceleration, jerk;
  bool jerk_published;
  const char* source;
};

// Why these numbers (docs/trajectory.md has the references):
//  - Panda: Franka's published joint limits (FCI "robot and interface specifications").
//  - UR5 (CB3): 180 deg/s per joint from the datasheet (the benchmark URDF says 3.15-3.2 rad/s);
//    5 rad/s^2, the value Universal Robots' MoveIt configuration ships as conservative.
//  - LBR iiwa 14 R820 (also on the KMR iiwa): KUKA's brochure velocities; accelerations measured
//    by Larsen (Chalmers 2019) as used by Drake.
//  - KMR base and fingers: our conservative choices.
// Where no jerk limit is published, jerk = acceleration / 50 ms: full acceleration is reached in
// 50 ms (200 ms for the mobile base), which keeps the profile smooth without costing much time.
constexpr char kFranka[] = "Franka published limits";
constexpr char kUr5[] = "UR5 datasheet velocity; UR MoveIt acceleration 5 rad/s^2; jerk default (a/50 ms)";
constexpr char kIiwa[] = "LBR iiwa 14 R820: KUKA velocity, measured acceleration (Drake); jerk default (a/50 ms)";
constexpr char kKmr[] = "KMR base: default 0.5 m/s^2 or rad/s^2, jerk a/200 ms";
constexpr char kFinger[] = "gripper finger: default 1 m/s^2, jerk a/50 ms";

const TableRow kTable[] = {
    {"panda_joint1", kNone, 15.0, 7500.0, true, kFranka},
    {"panda_joint2", kNone, 7.5, 3750.0, true, kFranka},
    {"panda_joint3", kNone, 10.0, 5000.0, true, kFranka},
    {"panda_joint4", kNone, 12.5, 6250.0, true, kFranka},
    {"panda_joint5", kNone, 15.0, 7500.0, true, kFranka},
    {"panda_joint6", kNone, 20.0, 10000.0, true, kFranka},
    {"panda_joint7", kNone, 20.0, 10000.0, true, kFranka},
    {"shoulder_pan_joint", 180 * kDeg, 5.0, 100.0, false, kUr5},
    {"shoulder_lift_joint", 180 * kDeg, 5.0, 100.0, false, kUr5},
    {"elbow_joint", 180 * kDeg, 5.0, 100.0, false, kUr5},
    {"wrist_1_joint", 180 * kDeg, 5.0, 100.0, false, kUr5},
    {"wrist_2_joint", 180 * kDeg, 5.0, 100.0, false, kUr5},
    {"wrist_3_joint", 180 * kDeg, 5.0, 100.0, false, kUr5},
    {"iiwa_joint_1", 85 * kDeg, 8.57, 8.57 / 0.05, false, kIiwa},
    {"iiwa_joint_2", 85 * kDeg, 8.57, 8.57 / 0.05, false, kIiwa},
    {"iiwa_joint_3", 100 * kDeg, 8.74, 8.74 / 0.05, false, kIiwa},
    {"iiwa_joint_4", 75 * kDeg, 11.36, 11.36 / 0.05, false, kIiwa},
    {"iiwa_joint_5", 130 * kDeg, 12.23, 12.23 / 0.05, false, kIiwa},
    {"iiwa_joint_6", 135 * kDeg, 15.72, 15.72 / 0.05, false, kIiwa},
    {"iiwa_joint_7", 135 * kDeg, 15.72, 15.72 / 0.05, false, kIiwa},
    {"world_to_help_0_joint", kNone, 0.5, 2.5, false, kKmr},
    {"help_0_to_help_1_joint", kNone, 0.5, 2.5, false, kKmr},
    {"help_1_to_kmr_joint", kNone, 0.5, 2.5, false, kKmr},
    {"panda_finger_joint1", kNone, 1.0, 20.0, false, kFinger},
    {"panda_finger_joint2", kNone, 1.0, 20.0, false, kFinger},
};

const TableRow* table_row(const std::string& joint) {
  for (const auto& r : kTable)
    if (joint == r.joint) return &r;
  return nullptr;
}

double positive_override(const std::map<std::string, double>& m, const std::string& joint, const char* what,
                         double value) {
  auto it = m.find(joint);
  if (it == m.end()) return value;
  if (!(std::isfinite(it->second) && it->second > 0))
    throw InputError("limit overrides", std::string(what) + "." + joint, "must be a finite number > 0");
  return it->second;
}

std::string number(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", x);
  return buf;
}

}  // namespace

JointLimitSet trajectory_limits(const RobotModel& model, const LimitOverrides& o) {
  for (double s : {o.velocity_scale, o.acceleration_scale})
    if (!(s > 0 && s <= 1)) throw InputError("limit overrides", "scale", "must be in (0, 1]");
  JointLimitSet l;
  const auto joints = model.configuration_joints();
  const long n = static_cast<long>(joints.size());
  l.lower.resize(n), l.upper.resize(n), l.velocity.resize(n), l.acceleration.resize(n), l.jerk.resize(n);
  for (long i = 0; i < n; ++i) {
    const Joint& j = *joints[i];
    l.names.push_back(j.name);
    l.lower[i] = j.limits.lower;
    l.upper[i] = j.limits.upper;
    const TableRow* row = table_row(j.name);
    double v = j.limits.velocity;
    if (!(v > 0) && !o.velocity.count(j.name))
      throw InputError(model.urdf_path, "joint " + j.name + " limit velocity",
                       "is not given (0): a trajectory needs a velocity limit for every joint");
    if (row) v = std::min(v, row->velocity_cap);
    v = positive_override(o.velocity, j.name, "velocity", v);
    double a = row ? row->acceleration : 0.0;
    a = positive_override(o.acceleration, j.name, "acceleration", a);
    if (!(a > 0))
      throw InputError(model.urdf_path, "joint " + j.name,
                       "no acceleration limit known for this joint (the URDF has none and it is not in "
                       "demoplan's table): give one as an override");
    double jk = row ? row->jerk : a / 0.05;
    jk = positive_override(o.jerk, j.name, "jerk", jk);
    l.velocity[i] = v * o.velocity_scale;
    l.acceleration[i] = a * o.acceleration_scale;
    l.jerk[i] = jk * o.acceleration_scale;
    l.jerk_published.push_back(row && row->jerk_published && !o.jerk.count(j.name));
    std::string src = row ? row->source : "default jerk a/50 ms";
    if (o.velocity.count(j.name) || o.acceleration.count(j.name) || o.jerk.count(j.name)) src += " (overridden)";
    if (o.velocity_scale != 1.0 || o.acceleration_scale != 1.0) src += " (scaled)";
    l.sources.push_back(src);
  }
  return l;
}

void check_path_within_limits(const Path& path, const JointLimitSet& limits, const std::string& source,
                              double tolerance) {
  if (path.joint_names != limits.names) {
    std::string names;
    for (const auto& n : limits.names) names += (names.empty() ? "" : ", ") + n;
    throw InputError(source, "joint_names", "must be the robot's configuration joints: " + names);
  }
  for (size_t k = 0; k < path.waypoints.size(); ++k) {
    const Eigen::VectorXd& q = path.waypoints[k].q;
    for (long j = 0; j < q.size(); ++j) {
      if (std::isfinite(q[j]) && q[j] >= limits.lower[j] - tolerance && q[j] <= limits.upper[j] + tolerance)
        continue;
      throw InputError(source, "waypoints[" + std::to_string(k) + "].q[" + std::to_string(j) + "]",
                       limits.names[j] + " = " + number(q[j]) + " is beyond its limit [" +
                           number(limits.lower[j]) + ", " + number(limits.upper[j]) + "]");
    }
  }
}

std::vector<std::string> describe_limits(const JointLimitSet& l, const std::vector<int>& joints) {
  std::vector<std::string> out;
  for (int j : joints)
    out.push_back(l.names[j] + ": position [" + number(l.lower[j]) + ", " + number(l.upper[j]) + "], velocity " +
                  number(l.velocity[j]) + ", acceleration " + number(l.acceleration[j]) + ", jerk " +
                  number(l.jerk[j]) + " (" + l.sources[j] + ")");
  return out;
}

}  // namespace demoplan
