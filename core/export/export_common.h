#pragma once
// What every program writer shares: its input (path, trajectory, limits, robot), which joints are
// the arm, the mobile base and the gripper, the motion blocks between stops and the header comment.
#include <string>
#include <vector>

#include "core/model/robot_model.h"
#include "core/path/path.h"
#include "core/trajectory/joint_limits.h"
#include "core/trajectory/trajectory.h"

namespace demoplan {

// Configuration slots by role. The gripper's fingers are commanded separately from the joint
// motion (open/close at the releases and grasps), so writers export arm and base joints only.
struct RobotAxes {
  std::vector<int> arm, base, gripper;
  int tcp_link = -1;  // the gripper link, for Cartesian blend radii
};

// gripper_link: the SRDF gripper's link; base_joints: the mobile base's joint names (robots.json
// base_dofs). Throws InputError when the gripper link is not in the model.
RobotAxes robot_axes(const RobotModel& model, const std::string& gripper_link,
                     const std::vector<std::string>& base_joints);
// base_dofs.joints of the robot in <data_dir>/robots/robots.json; empty for a fixed robot.
std::vector<std::string> benchmark_base_joints(const std::string& data_dir, const std::string& robot);

struct ExportOptions {
  std::string robot;   // e.g. "ur5"
  std::string source;  // the path file the program comes from
  double rate = 0;     // Hz of sampled output (csv, ros-yaml, URScript servoj); 0: the format's default
  // Digital outputs driving the gripper: `close_output` high closes; with open_output >= 0 that
  // output high opens (and close_output goes low), else close_output low opens.
  int close_output = -1;  // -1: the format's default (UR 0, KRL 1)
  int open_output = -1;
  double gripper_wait = 0.5;  // s to wait after a gripper command
  bool servoj = false;        // URScript: a servoj stream instead of movej waypoints
  bool krl_ptp = false;       // KRL: PTP with approximation instead of PTP_SPLINE blocks
};

// What a writer turns into a program: the path, its timing and the robot.
struct ProgramInput {
  const Path& path;
  const Trajectory& trajectory;
  const JointLimitSet& limits;
  const RobotModel& model;
  const RobotAxes& axes;
  const ExportOptions& options;
};

// The path cut at its stops: each block runs from one resting waypoint to the next; the gripper
// action, if any, happens at the block's last waypoint.
struct MotionBlock {
  size_t first = 0, last = 0;  // waypoint indices
};
std::vector<MotionBlock> motion_blocks(const Trajectory& trajectory);

// Header comment lines (without comment markers): robot, source, limits, timing, gripper.
std::vector<std::string> header_lines(const ProgramInput& input, const std::string& format);

std::string fixed(double x, int decimals);
// `text` with every character other than a letter or digit made '_', and `prefix` in front when
// it does not start with a letter: a name most controller languages accept.
std::string identifier(const std::string& text, const std::string& prefix);
// identifier() of a file name's stem (prefix "p_"), at most max_length characters.
std::string identifier_from_file(const std::string& path, size_t max_length);
// Values of q at the given slots.
std::vector<double> pick(const Eigen::VectorXd& q, const std::vector<int>& slots);
const char* action_word(GripperAction a);  // "grasp", "release", "none"

}  // namespace demoplan
