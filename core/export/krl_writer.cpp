#include "core/export/krl_writer.h"

#include <cctype>
#include <cmath>
#include <filesystem>
#include <sstream>

#include "core/error.h"

namespace demoplan {

namespace {

// E6AXIS components in order A1..A6, E1..E6, from the arm's joints.
std::vector<std::string> axis_names(size_t arm_joints) {
  if (arm_joints == 7) return {"A1", "A2", "E1", "A3", "A4", "A5", "A6"};
  std::vector<std::string> out;
  for (size_t i = 0; i < arm_joints; ++i) out.push_back(i < 6 ? "A" + std::to_string(i + 1) : "E" + std::to_string(i - 5));
  return out;
}

std::string e6axis(const Eigen::VectorXd& q, const std::vector<int>& arm, const std::vector<std::string>& names) {
  static const char* order[] = {"A1", "A2", "A3", "A4", "A5", "A6", "E1", "E2", "E3", "E4", "E5", "E6"};
  std::string s = "{";
  for (int i = 0; i < 12; ++i) {
    double deg = 0;
    for (size_t j = 0; j < names.size(); ++j)
      if (names[j] == order[i]) deg = q[arm[j]] * 180.0 / M_PI;
    s += std::string(i ? "," : "") + order[i] + " " + fixed(deg, 9);
  }
  return s + "}";
}

class KrlWriter final : public ProgramWriter {
public:
  KrlWriter() : ProgramWriter({"krl", "KUKA KRL (.src + .dat)", ".src", 100.0}) {}
  // NAME.src: KRL names are at most 24 characters; upper case by KUKA's habit.
  std::string file_name(const std::string& stem) const override {
    std::string name = file_stem(stem).substr(0, 24);
    for (char& c : name) c = char(std::toupper(static_cast<unsigned char>(c)));
    return name + format().extension;
  }
  ProgramOutput write(const ProgramInput& input, const std::string& file) const override;
};

ProgramOutput KrlWriter::write(const ProgramInput& input, const std::string& file) const {
  const RobotAxes& ax = input.axes;
  if (!ax.base.empty())
    throw InputError(file, "robot", input.options.robot + " has a mobile base, which a KR C4 does not drive: use the sunrise format");
  if (ax.arm.empty() || ax.arm.size() > 12)
    throw InputError(file, "robot", "KRL E6AXIS holds 1 to 12 axes; " + input.options.robot + " has " + std::to_string(ax.arm.size()));
  const std::filesystem::path src(file);
  if (src.extension() != ".src") throw InputError(file, "", "a KRL module is written as NAME.src (and NAME.dat)");
  const std::string name = src.stem().string();
  if (name.empty() || name.size() > 24 || !std::isalpha(static_cast<unsigned char>(name[0])) ||
      identifier_from_file(file, 24) != name)
    throw InputError(file, "", "the module name '" + name + "' must be 1-24 letters, digits or '_', starting with a letter");
  const ExportOptions& o = input.options;
  const int close = o.close_output >= 0 ? o.close_output : 1;
  const auto names = axis_names(ax.arm.size());
  const auto& W = input.path.waypoints;
  const Trajectory& tr = input.trajectory;

  std::ostringstream h;
  for (const auto& line : header_lines(input, o.krl_ptp ? "KRL PTP C_PTP" : "KRL PTP_SPLINE")) h << "; " << line << "\n";
  h << "; Axes: ";
  for (size_t j = 0; j < names.size(); ++j) h << names[j] << "=" << input.limits.names[ax.arm[j]] << " ";
  h << "(degrees)\n; Gripper: $OUT[" << close << "] TRUE = close"
    << (o.open_output >= 0 ? ", $OUT[" + std::to_string(o.open_output) + "] TRUE = open" : ", FALSE = open") << "\n";

  std::ostringstream s;
  s << "&ACCESS RVP\n&REL 1\nDEF " << name << "( )\n" << h.str();
  s << ";FOLD INI\n  BAS(#INITMOV, 0)\n;ENDFOLD\n";
  for (int i = 1; i <= 6; ++i) s << "$VEL_AXIS[" << i << "] = 100\n$ACC_AXIS[" << i << "] = 100\n";
  if (o.krl_ptp) s << "$APO.CPTP = 20\n";
  auto gripper = [&](bool closed) {
    if (o.open_output >= 0) s << "$OUT[" << o.open_output << "] = " << (closed ? "FALSE" : "TRUE") << "\n";
    s << "$OUT[" << close << "] = " << (closed ? "TRUE" : "FALSE") << "\nWAIT SEC " << fixed(o.gripper_wait, 3) << "\n";
  };
  s << "; waypoint 0 (start)\nPTP XP0\n";
  if (tr.starts_closed) gripper(true);
  for (const MotionBlock& b : motion_blocks(tr)) {
    s << "; waypoints " << b.first << ".." << b.last << "\n";
    if (!o.krl_ptp) s << "PTP_SPLINE\n";
    for (size_t k = b.first + 1; k <= b.last; ++k) {
      if (o.krl_ptp) s << "PTP XP" << k << (k < b.last ? " C_PTP" : "") << "\n";
      else s << "  SPTP XP" << k << "\n";
    }
    if (!o.krl_ptp) s << "ENDSPLINE\n";
    if (W[b.last].action == GripperAction::Grasp) s << "; grasp\n", gripper(true);
    if (W[b.last].action == GripperAction::Release) s << "; release\n", gripper(false);
  }
  s << "END\n";

  std::ostringstream d;
  d << "&ACCESS RVP\n&REL 1\nDEFDAT " << name << " PUBLIC\n" << h.str();
  for (size_t k = 0; k < W.size(); ++k) d << "DECL E6AXIS XP" << k << "=" << e6axis(W[k].q, ax.arm, names) << "\n";
  d << "ENDDAT\n";

  const std::string dat = (src.parent_path() / (name + ".dat")).string();
  return {{{file, s.str()}, {dat, d.str()}}, {}, 0};
}

}  // namespace

const ProgramWriter& krl_writer() {
  static const KrlWriter writer;
  return writer;
}

}  // namespace demoplan
