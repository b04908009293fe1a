#include "ui/document/program_export.h"

#include <cctype>
#include <fstream>
#include <sstream>

#include "core/export/exporter.h"
#include "core/trajectory/joint_limits.h"
#include "core/trajectory/time_parameterization.h"
#include "core/trajectory/trajectory_checker.h"
#include "core/validation/trajectory_collisions.h"

namespace demoplan::ui {

std::vector<ProgramFormat> program_formats() {
  static const std::vector<ProgramFormat> known = {
      {"urscript", "Universal Robots (URScript)", ".script"},
      {"krl", "KUKA KRL (.src + .dat)", ".src"},
      {"sunrise", "KUKA Sunrise (Java application)", ".java"},
      {"franka", "Franka (libfranka C++)", ".cpp"},
      {"ros-yaml", "ROS joint trajectory (YAML)", ".yaml"},
      {"csv", "CSV (time, joints, gripper)", ".csv"}};
  std::vector<ProgramFormat> out;
  for (const std::string& id : export_formats()) {
    bool found = false;
    for (const auto& f : known)
      if (f.id == id) out.push_back(f), found = true;
    if (!found) out.push_back({id, id, "." + id});
  }
  return out;
}

std::string program_file_name(const std::string& format, const std::string& stem_in) {
  std::string stem;
  for (char c : stem_in) stem += std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
  if (stem.empty() || !std::isalpha(static_cast<unsigned char>(stem[0]))) stem = "job_" + stem;
  if (format == "krl") {
    std::string upper = stem.substr(0, 24);
    for (char& c : upper) c = char(std::toupper(static_cast<unsigned char>(c)));
    return upper + ".src";
  }
  if (format == "sunrise") {
    std::string cls;
    bool up = true;
    for (char c : stem) {
      if (c == '_') {
        up = true;
        continue;
      }
      cls += up ? char(std::toupper(static_cast<unsigned char>(c))) : c;
      up = false;
    }
    return cls + ".java";
  }
  for (const auto& f : program_formats())
    if (f.id == format) return stem + f.extension;
  return stem + "." + format;
}

ProgramExport export_program_file(const Scene& scene, const Path& path, const std::string& data_dir,
                                  const ProgramSettings& s, const std::string& file) {
  ProgramExport r;
  try {
    const RobotModel& model = scene.robot.model;
    if (scene.robot.srdf.grippers.empty()) throw std::runtime_error("the robot has no gripper in its SRDF");
    LimitOverrides overrides;
    overrides.velocity_scale = s.velocity_scale;
    overrides.acceleration_scale = s.acceleration_scale;
    const JointLimitSet limits = trajectory_limits(model, overrides);
    TimingOptions timing;
    timing.source = file;
    timing.blend_length = s.blend;
    const CollisionChecker checker(scene);
    const ClearTrajectory clear = time_parameterize_clear(scene, checker, path, limits, timing);
    const Trajectory& tr = clear.trajectory;
    r.blends = tr.blends.size();
    r.rests_added = clear.rests_added.size();
    r.duration_s = tr.duration;
    r.trapezoid_duration_s = tr.trapezoid_duration;
    const double rate = s.format == "franka" ? 1000.0 : s.rate > 0 ? s.rate : 100.0;
    const CheckReport check = check_trajectory(tr.sample(rate, true), path, limits);
    r.check_ok = check.ok;
    r.violations = check.violations;
    r.peak_velocity_ratio = check.peak_velocity_ratio;
    r.peak_acceleration_ratio = check.peak_acceleration_ratio;
    const RobotAxes axes =
        robot_axes(model, scene.robot.srdf.grippers.front().link, benchmark_base_joints(data_dir, scene.robot.name));
    std::vector<int> joints = axes.arm;
    joints.insert(joints.end(), axes.base.begin(), axes.base.end());
    r.limits = describe_limits(limits, joints);
    if (!check.ok) {
      r.error = "the timed trajectory fails the independent check: " +
                (check.violations.empty() ? std::string("(no detail)") : check.violations.front());
      return r;
    }
    ExportOptions eo;
    eo.robot = scene.robot.name;
    eo.source = path.task + " " + path.robot + " pose " + std::to_string(path.robot_pose);
    eo.rate = s.rate;
    eo.close_output = s.gripper_output;
    const ExportResult written = export_program(s.format, {path, tr, limits, model, axes, eo}, file);
    r.files = written.files;
    r.warnings = written.warnings;
    for (const auto& f : written.files) {
      std::ifstream in(f);
      std::stringstream ss;
      ss << in.rdbuf();
      if (written.files.size() > 1) r.text += "// ---- " + f.substr(f.find_last_of('/') + 1) + "\n";
      r.text += ss.str();
      if (!r.text.empty() && r.text.back() != '\n') r.text += '\n';
    }
    r.ok = true;
  } catch (const std::exception& e) {
    r.error = e.what();
  }
  return r;
}

}  // namespace demoplan::ui
