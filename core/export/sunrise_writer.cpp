#include "core/export/sunrise_writer.h"

#include <cctype>
#include <cmath>
#include <filesystem>
#include <sstream>

#include "core/error.h"

namespace demoplan {

namespace {

class SunriseWriter final : public ProgramWriter {
public:
  SunriseWriter() : ProgramWriter({"sunrise", "KUKA Sunrise (Java application)", ".java", 100.0}) {}
  // CLASS.java, the class name in CamelCase: "shelf_1_panda" -> "Shelf1Panda".
  std::string file_name(const std::string& stem) const override {
    std::string cls;
    bool up = true;
    for (char c : file_stem(stem)) {
      if (c == '_') {
        up = true;
        continue;
      }
      cls += up ? char(std::toupper(static_cast<unsigned char>(c))) : c;
      up = false;
    }
    return cls + format().extension;
  }
  ProgramOutput write(const ProgramInput& input, const std::string& file) const override;
};

ProgramOutput SunriseWriter::write(const ProgramInput& input, const std::string& file) const {
  const RobotAxes& ax = input.axes;
  if (ax.arm.size() != 7) throw InputError(file, "robot", "Sunrise drives the 7-axis LBR iiwa; " + input.options.robot + " has " + std::to_string(ax.arm.size()) + " arm joints");
  if (!ax.base.empty() && ax.base.size() != 3) throw InputError(file, "robot", "a KMR base has 3 joints (x, y, theta)");
  const std::filesystem::path path(file);
  const std::string cls = path.stem().string();
  if (path.extension() != ".java" || identifier_from_file(file, 200) != cls)
    throw InputError(file, "", "a Sunrise application is written as CLASSNAME.java with CLASSNAME a Java identifier");
  const ExportOptions& o = input.options;
  const auto& W = input.path.waypoints;
  const Trajectory& tr = input.trajectory;
  const bool mobile = !ax.base.empty();

  std::ostringstream s;
  for (const auto& line : header_lines(input, "Sunrise Java")) s << "// " << line << "\n";
  s << "// Arm joints A1..A7: ";
  for (int j : ax.arm) s << input.limits.names[j] << " ";
  s << "\n// Gripper: gripperIO.setOutputX3Pin1(true) = close, false = open (MediaFlangeIOGroup).\n";
  if (mobile)
    s << "// KMR: where the base moves, the platform moves first (MobilePlatformRelativeMotion dx, dy in m,\n"
         "// dtheta in rad, in the platform frame at the move's start), then the arm: re-check these\n"
         "// segments for collisions, they are not the planned simultaneous motion.\n";
  s << "package application;\n\n"
       "import static com.kuka.roboticsAPI.motionModel.BasicMotions.ptp;\n\n"
       "import javax.inject.Inject;\n\n"
       "import com.kuka.common.ThreadUtil;\n"
       "import com.kuka.generated.ioAccess.MediaFlangeIOGroup;\n"
       "import com.kuka.roboticsAPI.applicationModel.RoboticsAPIApplication;\n"
       "import com.kuka.roboticsAPI.deviceModel.JointPosition;\n"
       "import com.kuka.roboticsAPI.deviceModel.LBR;\n"
       "import com.kuka.roboticsAPI.motionModel.SplineJP;\n";
  if (mobile)
    s << "import com.kuka.roboticsAPI.deviceModel.kmp.KmpOmniMove;\n"
         "import com.kuka.roboticsAPI.motionModel.kmp.MobilePlatformRelativeMotion;\n";
  s << "\npublic class " << cls << " extends RoboticsAPIApplication {\n"
    << "  @Inject private LBR lbr;\n";
  if (mobile) s << "  @Inject private KmpOmniMove kmp;\n";
  s << "  @Inject private MediaFlangeIOGroup gripperIO;\n"
    << "  private static final double VELOCITY_REL = 1.0;  // of the LBR's maximum joint speeds\n"
    << "  private static final long GRIPPER_WAIT_MS = " << std::lround(o.gripper_wait * 1000) << ";\n\n"
    << "  // Waypoints of the path, joint angles in radians.\n"
    << "  private static final JointPosition[] WAYPOINTS = {\n";
  for (size_t k = 0; k < W.size(); ++k) {
    s << "    new JointPosition(";
    for (size_t j = 0; j < ax.arm.size(); ++j) s << (j ? ", " : "") << fixed(W[k].q[ax.arm[j]], 12);
    s << "),  // " << k << (tr.stops[k] ? " rest" : "") << "\n";
  }
  s << "  };\n\n  @Override\n  public void run() {\n";
  s << "    lbr.move(ptp(WAYPOINTS[0]).setJointVelocityRel(VELOCITY_REL));  // to the start\n";
  if (tr.starts_closed) s << "    closeGripper();\n";
  auto base_moves = [&](size_t k) {
    if (!mobile) return false;
    for (int b : ax.base)
      if (W[k].q[b] != W[k - 1].q[b]) return true;
    return false;
  };
  for (const MotionBlock& b : motion_blocks(tr)) {
    bool platform = false;
    for (size_t k = b.first + 1; k <= b.last; ++k) platform = platform || base_moves(k);
    s << "    // waypoints " << b.first << ".." << b.last << "\n";
    if (!platform) {
      s << "    lbr.move(new SplineJP(";
      for (size_t k = b.first + 1; k <= b.last; ++k) s << (k > b.first + 1 ? ", " : "") << "ptp(WAYPOINTS[" << k << "])";
      s << ").setJointVelocityRel(VELOCITY_REL));\n";
    } else {
      for (size_t k = b.first + 1; k <= b.last; ++k) {
        if (base_moves(k)) {
          const double th = W[k - 1].q[ax.base[2]];
          const double dx = W[k].q[ax.base[0]] - W[k - 1].q[ax.base[0]], dy = W[k].q[ax.base[1]] - W[k - 1].q[ax.base[1]];
          s << "    kmp.move(new MobilePlatformRelativeMotion(" << fixed(std::cos(th) * dx + std::sin(th) * dy, 12) << ", "
            << fixed(-std::sin(th) * dx + std::cos(th) * dy, 12) << ", "
            << fixed(W[k].q[ax.base[2]] - th, 12) << "));\n";
        }
        s << "    lbr.move(ptp(WAYPOINTS[" << k << "]).setJointVelocityRel(VELOCITY_REL));\n";
      }
    }
    if (W[b.last].action == GripperAction::Grasp) s << "    closeGripper();\n";
    if (W[b.last].action == GripperAction::Release) s << "    openGripper();\n";
  }
  s << "  }\n\n"
    << "  private void closeGripper() {\n    gripperIO.setOutputX3Pin1(true);\n    ThreadUtil.milliSleep(GRIPPER_WAIT_MS);\n  }\n\n"
    << "  private void openGripper() {\n    gripperIO.setOutputX3Pin1(false);\n    ThreadUtil.milliSleep(GRIPPER_WAIT_MS);\n  }\n}\n";
  ProgramOutput result;
  if (mobile) result.warnings.push_back("the KMR platform and arm move one after the other where the base moves: re-check those segments");
  result.files.push_back({file, s.str()});
  return result;
}

}  // namespace

const ProgramWriter& sunrise_writer() {
  static const SunriseWriter writer;
  return writer;
}

}  // namespace demoplan
