#include "core/export/urscript_writer.h"

#include <cmath>
#include <sstream>

#include "core/error.h"
#include "core/model/kinematics.h"

namespace demoplan {

namespace {

std::string joint_list(const Eigen::VectorXd& q, const std::vector<int>& slots) {
  std::string s = "[";
  for (size_t i = 0; i < slots.size(); ++i) s += (i ? ", " : "") + fixed(q[slots[i]], 10);
  return s + "]";
}

class UrScriptWriter final : public ProgramWriter {
public:
  // 125 Hz: a CB3's servoj cycle (an e-Series also takes 500).
  UrScriptWriter() : ProgramWriter({"urscript", "Universal Robots (URScript)", ".script", 125.0}) {}
  ProgramOutput write(const ProgramInput& input, const std::string& file) const override;
};

ProgramOutput UrScriptWriter::write(const ProgramInput& input, const std::string& file) const {
  const RobotAxes& ax = input.axes;
  if (ax.arm.size() != 6 || !ax.base.empty())
    throw InputError(file, "robot", "URScript needs a fixed 6-axis arm; " + input.options.robot + " has " +
                                        std::to_string(ax.arm.size()) + " arm joints" +
                                        (ax.base.empty() ? "" : " and a mobile base"));
  const ExportOptions& o = input.options;
  const double rate = sample_rate(o);
  if (o.servoj && rate != 125.0 && rate != 500.0)
    throw InputError(file, "rate", "a servoj stream runs at 125 Hz (CB3) or 500 Hz (e-Series), not " + fixed(rate, 3));
  const int close = o.close_output >= 0 ? o.close_output : 0;
  const std::string name = identifier_from_file(file, 60);
  const auto& W = input.path.waypoints;
  const Trajectory& tr = input.trajectory;

  // movej's a and v bound the leading joint: the smallest of the arm's limits.
  double a = 1e9, v = 1e9;
  for (int j : ax.arm) a = std::min(a, input.limits.acceleration[j]), v = std::min(v, input.limits.velocity[j]);

  std::ostringstream s;
  for (const auto& line : header_lines(input, o.servoj ? "URScript servoj" : "URScript movej")) s << "# " << line << "\n";
  s << "# Joints: ";
  for (int j : ax.arm) s << input.limits.names[j] << " ";
  s << "\n# Gripper: standard digital output " << close << " high = close"
    << (o.open_output >= 0 ? ", output " + std::to_string(o.open_output) + " high = open" : ", low = open") << "\n";
  if (o.servoj) s << "# servoj stream at " << fixed(rate, 0) << " Hz from the timed trajectory.\n";
  else s << "# movej: a = " << fixed(a, 4) << " rad/s^2, v = " << fixed(v, 4) << " rad/s; r = blend radius (m).\n";
  s << "def " << name << "():\n";
  s << "  def gripper_close():\n";
  if (o.open_output >= 0) s << "    set_standard_digital_out(" << o.open_output << ", False)\n";
  s << "    set_standard_digital_out(" << close << ", True)\n    sleep(" << fixed(o.gripper_wait, 3) << ")\n  end\n";
  s << "  def gripper_open():\n    set_standard_digital_out(" << close << ", False)\n";
  if (o.open_output >= 0) s << "    set_standard_digital_out(" << o.open_output << ", True)\n";
  s << "    sleep(" << fixed(o.gripper_wait, 3) << ")\n  end\n";
  s << "  # waypoint 0 (start)\n  movej(" << joint_list(W[0].q, ax.arm) << ", a=" << fixed(a, 4) << ", v=" << fixed(v, 4)
    << ", r=0)\n";
  if (tr.starts_closed) s << "  gripper_close()\n";

  ProgramOutput result;
  // TCP positions for the blend radii: at most 2 cm and under half the distance to either
  // neighbour, so consecutive blends never overlap.
  std::vector<Eigen::Vector3d> tcp;
  for (const auto& w : W) tcp.push_back(link_pose(input.model, w.q, Pose::Identity(), ax.tcp_link).translation());
  for (const MotionBlock& b : motion_blocks(tr)) {
    if (o.servoj) {
      const double t0 = tr.waypoint_times[b.first], t1 = tr.waypoint_times[b.last];
      const long steps = static_cast<long>(std::ceil((t1 - t0) * rate - 1e-9));
      s << "  # waypoints " << b.first << ".." << b.last << ": " << steps << " servoj steps from t = " << fixed(t0, 6)
        << " s\n";
      for (long i = 1; i <= steps; ++i) {
        const double t = std::min(t1, t0 + static_cast<double>(i) / rate);
        s << "  servoj(" << joint_list(tr.motion.at(t).q, ax.arm) << ", 0, 0, " << fixed(1.0 / rate, 4) << ", 0.1, 300)\n";
      }
      result.samples += static_cast<size_t>(steps);
      s << "  # waypoint " << b.last << " (rest)\n  stopj(" << fixed(a, 4) << ")\n";
    } else {
      for (size_t k = b.first + 1; k <= b.last; ++k) {
        double r = 0;
        if (!tr.stops[k])
          r = std::min({0.02, 0.45 * (tcp[k] - tcp[k - 1]).norm(), 0.45 * (tcp[k + 1] - tcp[k]).norm()});
        s << "  # waypoint " << k << (tr.stops[k] ? " (rest)" : "") << "\n  movej(" << joint_list(W[k].q, ax.arm)
          << ", a=" << fixed(a, 4) << ", v=" << fixed(v, 4) << ", r=" << fixed(r, 5) << ")\n";
      }
    }
    if (W[b.last].action == GripperAction::Grasp) s << "  gripper_close()\n";
    if (W[b.last].action == GripperAction::Release) s << "  gripper_open()\n";
  }
  s << "end\n";
  result.files.push_back({file, s.str()});
  return result;
}

}  // namespace

const ProgramWriter& urscript_writer() {
  static const UrScriptWriter writer;
  return writer;
}

}  // namespace demoplan
