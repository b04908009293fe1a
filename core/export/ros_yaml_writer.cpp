#include "core/export/ros_yaml_writer.h"

#include <cmath>
#include <sstream>

namespace demoplan {

namespace {

std::string list(const Eigen::VectorXd& x, const std::vector<int>& slots) {
  std::string s = "[";
  for (size_t i = 0; i < slots.size(); ++i) s += (i ? ", " : "") + fixed(x[slots[i]], 10);
  return s + "]";
}

class RosYamlWriter final : public ProgramWriter {
public:
  RosYamlWriter() : ProgramWriter({"ros-yaml", "ROS joint trajectory (YAML)", ".yaml", 100.0}) {}
  ProgramOutput write(const ProgramInput& input, const std::string& file) const override;
};

ProgramOutput RosYamlWriter::write(const ProgramInput& input, const std::string& file) const {
  const Trajectory& tr = input.trajectory;
  const auto& W = input.path.waypoints;
  std::vector<int> joints = input.axes.base;
  joints.insert(joints.end(), input.axes.arm.begin(), input.axes.arm.end());
  const double rate = sample_rate(input.options);
  const auto samples = tr.sample(rate, true);

  std::ostringstream s;
  for (const auto& line : header_lines(input, "ROS trajectory_msgs/JointTrajectory YAML")) s << "# " << line << "\n";
  s << "# Points every " << fixed(1.0 / rate, 6) << " s and at each waypoint; time_from_start from each segment's start.\n";
  s << "format: demoplan-ros-joint-trajectories\nversion: 1\nrobot: " << input.options.robot << "\n";
  s << "initial_gripper: " << (tr.starts_closed ? "closed" : "open") << "\nsegments:\n";
  ProgramOutput result;
  size_t i = 0;
  for (const MotionBlock& b : motion_blocks(tr)) {
    const double t0 = tr.waypoint_times[b.first], t1 = tr.waypoint_times[b.last];
    s << "  - waypoints: [" << b.first << ", " << b.last << "]\n";
    s << "    trajectory:\n      header:\n        stamp: {sec: 0, nanosec: 0}\n        frame_id: \"\"\n      joint_names: [";
    for (size_t j = 0; j < joints.size(); ++j) s << (j ? ", " : "") << input.limits.names[joints[j]];
    s << "]\n      points:\n";
    while (i < samples.size() && samples[i].t < t0 - 1e-12) ++i;
    for (; i < samples.size() && samples[i].t <= t1 + 1e-12; ++i) {
      const auto& p = samples[i];
      const double rel = std::max(0.0, p.t - t0);
      long sec = static_cast<long>(std::floor(rel));
      long nsec = std::lround((rel - sec) * 1e9);
      if (nsec >= 1000000000) ++sec, nsec -= 1000000000;
      s << "        - positions: " << list(p.q, joints) << "\n          velocities: " << list(p.v, joints)
        << "\n          accelerations: " << list(p.a, joints) << "\n          effort: []\n"
        << "          time_from_start: {sec: " << sec << ", nanosec: " << nsec << "}\n";
      ++result.samples;
    }
    --i;  // the rest ending this segment starts the next one
    s << "    gripper_after: " << action_word(W[b.last].action) << "\n";
  }
  result.files.push_back({file, s.str()});
  return result;
}

}  // namespace

const ProgramWriter& ros_yaml_writer() {
  static const RosYamlWriter writer;
  return writer;
}

}  // namespace demoplan
