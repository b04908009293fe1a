#include "core/export/franka_writer.h"

#include <cmath>

#include "core/error.h"
#include "core/io/json_file.h"

namespace demoplan {

namespace {

constexpr double kRate = 1000.0;
// Franka's published joint ranges (the benchmark's Panda URDF is wider).
constexpr double kLower[7] = {-2.8973, -1.7628, -2.8973, -3.0718, -2.8973, -0.0175, -2.8973};
constexpr double kUpper[7] = {2.8973, 1.7628, 2.8973, -0.0698, 2.8973, 3.7525, 2.8973};

double round10(double x) { return std::round(x * 1e10) / 1e10; }

class FrankaWriter final : public ProgramWriter {
public:
  FrankaWriter() : ProgramWriter({"franka", "Franka (1 kHz JSON for libfranka)", ".json", kRate, /*fixed_rate=*/true}) {}
  ProgramOutput write(const ProgramInput& input, const std::string& file) const override;
};

ProgramOutput FrankaWriter::write(const ProgramInput& input, const std::string& file) const {
  const RobotAxes& ax = input.axes;
  if (ax.arm.size() != 7 || !ax.base.empty())
    throw InputError(file, "robot", "the Franka format is for the 7-axis Panda; " + input.options.robot + " has " +
                                        std::to_string(ax.arm.size()) + " arm joints" + (ax.base.empty() ? "" : " and a mobile base"));
  if (input.options.rate > 0 && input.options.rate != kRate)
    throw InputError(file, "rate", "libfranka runs at 1000 Hz, not " + fixed(input.options.rate, 3));
  const auto& W = input.path.waypoints;
  const Trajectory& tr = input.trajectory;
  ProgramOutput result;
  for (size_t k = 0; k < W.size(); ++k)
    for (size_t j = 0; j < 7; ++j) {
      const double q = W[k].q[ax.arm[j]];
      if (q < kLower[j] || q > kUpper[j]) {
        result.warnings.push_back("waypoint " + std::to_string(k) + ": " + input.limits.names[ax.arm[j]] + " = " + fixed(q, 4) +
                                  " is outside Franka's published range [" + fixed(kLower[j], 4) + ", " + fixed(kUpper[j], 4) + "]");
        break;
      }
    }

  Json names = Json::array();
  for (int j : ax.arm) names.push_back(input.limits.names[j]);
  Json steps = Json::array(), waypoints = Json::array();
  auto q_of = [&](double t) {
    const Eigen::VectorXd q = tr.motion.at(t).q;
    Json row = Json::array();
    for (int j : ax.arm) row.push_back(round10(q[j]));
    return row;
  };
  waypoints.push_back({{"index", 0}, {"step", -1}, {"time", 0.0}, {"action", "none"}});
  if (tr.starts_closed) steps.push_back({{"type", "gripper"}, {"action", "grasp"}});
  for (const MotionBlock& b : motion_blocks(tr)) {
    const double t0 = tr.waypoint_times[b.first], t1 = tr.waypoint_times[b.last];
    const long n = static_cast<long>(std::ceil((t1 - t0) * kRate - 1e-9));
    Json q = Json::array();
    // Sample i at t0 + i ms; the last one at the rest (held there if the block is not a whole
    // number of milliseconds: velocity and acceleration are zero by then).
    for (long i = 0; i <= n; ++i) q.push_back(q_of(std::min(t1, t0 + static_cast<double>(i) / kRate)));
    result.samples += static_cast<size_t>(n + 1);
    const int step = static_cast<int>(steps.size());
    for (size_t k = b.first + 1; k <= b.last; ++k)
      waypoints.push_back({{"index", k}, {"step", step}, {"time", tr.waypoint_times[k] - t0}, {"action", action_word(W[k].action)}});
    steps.push_back({{"type", "motion"}, {"duration", static_cast<double>(n) / kRate}, {"q", q}});
    if (W[b.last].action == GripperAction::Grasp)
      steps.push_back({{"type", "gripper"}, {"action", "grasp"}, {"width", 0.0}, {"speed", 0.05}, {"force", 20.0},
                       {"epsilon_inner", 0.005}, {"epsilon_outer", 0.08}});
    if (W[b.last].action == GripperAction::Release)
      steps.push_back({{"type", "gripper"}, {"action", "release"}, {"width", 0.08}, {"speed", 0.1}});
  }
  const Json out{{"format", "demoplan-franka-trajectory"},
                 {"version", 1},
                 {"header", header_lines(input, "Franka JSON 1 kHz")},
                 {"units", "q in rad; one row per 1 ms; gripper width in m, speed in m/s, force in N"},
                 {"robot", input.options.robot},
                 {"rate_hz", kRate},
                 {"joint_names", names},
                 {"start", q_of(0.0)},
                 {"waypoints", waypoints},
                 {"steps", steps}};
  result.files.push_back({file, out.dump() + '\n'});  // as write_json_file_atomic(file, out, -1) wrote it
  return result;
}

}  // namespace

const ProgramWriter& franka_writer() {
  static const FrankaWriter writer;
  return writer;
}

}  // namespace demoplan
