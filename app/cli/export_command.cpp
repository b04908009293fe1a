// demoplan-cli export: time-parameterize a planned path within the robot's limits, check the
// result independently, and write it as a program for the robot's controller.
#include <iostream>
#include <memory>

#include <nlohmann/json.hpp>

#include "app/cli/command.h"
#include "core/demo/benchmark_scene.h"
#include "core/error.h"
#include "core/export/exporter.h"
#include "core/model/srdf.h"
#include "core/trajectory/time_parameterization.h"
#include "core/trajectory/trajectory_checker.h"
#include "core/validation/trajectory_collisions.h"

namespace demoplan::cli {

namespace {

struct ExportCommandOptions {
  std::string path_file, robot, format, out, data_dir;
  double rate = 0;
  bool json = false, servoj = false, krl_ptp = false;
  int gripper_output = -1, gripper_open_output = -1;
  double velocity_scale = 1.0, acceleration_scale = 1.0, blend = 0.1;
};

int run_export(const ExportCommandOptions& o) {
  const Path path = load_path(o.path_file);
  const std::string robot = o.robot.empty() ? path.robot : o.robot;
  if (robot != path.robot)
    throw InputError(o.path_file, "robot", "the path is for '" + path.robot + "', --robot says '" + robot + "'");
  const BenchmarkRobot info = load_benchmark_robot(o.data_dir, robot);
  const RobotModel model = load_urdf(info.urdf);
  const Srdf srdf = load_srdf(info.srdf);
  if (srdf.grippers.empty()) throw InputError(info.srdf, "gripper", "robot has no gripper");

  LimitOverrides overrides;
  overrides.velocity_scale = o.velocity_scale;
  overrides.acceleration_scale = o.acceleration_scale;
  const JointLimitSet limits = trajectory_limits(model, overrides);
  TimingOptions timing;
  timing.source = o.path_file;
  timing.blend_length = o.blend;
  // The blends cut the path's corners: check them against the path's scene, and rest at the
  // corners where they would touch something.
  if (path.task.empty()) throw InputError(o.path_file, "task", "is empty: the scene is needed to check the blends");
  const Scene scene = build_benchmark_scene(load_benchmark_task(o.data_dir, path.task), robot, path.robot_pose);
  const CollisionChecker checker(scene);
  const ClearTrajectory clear = time_parameterize_clear(scene, checker, path, limits, timing);
  const Trajectory& tr = clear.trajectory;

  // The independent check, at the output's own rate where it streams samples.
  const double rate = o.format == "franka" ? 1000.0 : o.rate > 0 ? o.rate : o.servoj ? 125.0 : 100.0;
  const auto samples = tr.sample(rate, true);
  const CheckReport check = check_trajectory(samples, path, limits);

  const RobotAxes axes = robot_axes(model, srdf.grippers.front().link, benchmark_base_joints(o.data_dir, robot));
  ExportOptions eo;
  eo.robot = robot;
  eo.source = o.path_file;
  eo.rate = o.rate;
  eo.close_output = o.gripper_output;
  eo.open_output = o.gripper_open_output;
  eo.servoj = o.servoj;
  eo.krl_ptp = o.krl_ptp;
  ExportResult written;
  if (check.ok) written = export_program(o.format, {path, tr, limits, model, axes, eo}, o.out);

  int stops = 0;
  for (char s : tr.stops) stops += s;
  std::cerr << "export " << o.format << " for " << robot << " from " << o.path_file << "\n"
            << "  waypoints            " << path.waypoints.size() << " (" << stops << " rests)\n"
            << "  duration             " << tr.duration << " s\n"
            << "  trapezoid duration   " << tr.trapezoid_duration << " s (ratio " << tr.trapezoid_duration / tr.duration << ")\n"
            << "  peak velocity        " << check.peak_velocity_ratio << " of the limit\n"
            << "  peak acceleration    " << check.peak_acceleration_ratio << " of the limit\n"
            << "  samples checked      " << samples.size() << " at " << rate << " Hz: "
            << (check.ok ? "ok" : "FAILED: " + check.violations.front()) << "\n"
            << "  blends               " << tr.blends.size() << " collision-free"
            << (clear.rests_added.empty() ? std::string()
                                          : "; " + std::to_string(clear.rests_added.size()) +
                                                " more rest(s) where a blend would touch the scene")
            << "\n";
  for (const auto& f : written.files) std::cerr << "  wrote                " << f << "\n";
  for (const auto& w : written.warnings) std::cerr << "  warning              " << w << "\n";
  if (o.json) {
    nlohmann::json j{{"format", o.format},
                     {"robot", robot},
                     {"path", o.path_file},
                     {"waypoints", path.waypoints.size()},
                     {"rests", stops},
                     {"duration_s", tr.duration},
                     {"trapezoid_duration_s", tr.trapezoid_duration},
                     {"trapezoid_ratio", tr.trapezoid_duration / tr.duration},
                     {"samples", samples.size()},
                     {"rate_hz", rate},
                     {"streamed_samples", written.samples},
                     {"peak_velocity_ratio", check.peak_velocity_ratio},
                     {"peak_acceleration_ratio", check.peak_acceleration_ratio},
                     {"peak_jerk_ratio", check.peak_jerk_ratio},
                     {"max_path_deviation", check.max_path_deviation},
                     {"check_ok", check.ok},
                     {"blends", tr.blends.size()},
                     {"rests_added_for_clearance", clear.rests_added.size()},
                     {"violations", check.violations},
                     {"files", written.files},
                     {"warnings", written.warnings}};
    std::cout << j.dump() << std::endl;
  }
  return check.ok ? kOk : kFailed;
}

}  // namespace

Command register_export_command(CLI::App& app) {
  auto o = std::make_shared<ExportCommandOptions>();
  CLI::App* sub = app.add_subcommand("export", "time a planned path within the robot's limits and write it as a robot program");
  sub->add_option("path", o->path_file, "path JSON (demoplan-path)")->required()->check(CLI::ExistingFile);
  sub->add_option("--robot", o->robot, "robot name from robots.json (default: the path's)");
  sub->add_option("--format", o->format, "urscript, krl, sunrise, franka, ros-yaml or csv")
      ->required()
      ->check(CLI::IsMember(export_formats()));
  sub->add_option("--out", o->out, "file to write (krl: NAME.src, NAME.dat beside it; sunrise: CLASS.java)")->required();
  sub->add_option("--rate", o->rate, "Hz of sampled output: csv and ros-yaml (default 100), URScript servoj (125 or 500); franka is 1000")
      ->check(CLI::PositiveNumber);
  sub->add_flag("--servoj", o->servoj, "URScript: stream servoj at --rate instead of movej waypoints");
  sub->add_flag("--krl-ptp", o->krl_ptp, "KRL: PTP with C_PTP approximation instead of PTP_SPLINE blocks");
  sub->add_option("--gripper-output", o->gripper_output, "digital output that closes the gripper (UR default 0, KRL 1)")
      ->check(CLI::NonNegativeNumber);
  sub->add_option("--gripper-open-output", o->gripper_open_output, "digital output that opens it, for two-output grippers")
      ->check(CLI::NonNegativeNumber);
  sub->add_option("--velocity-scale", o->velocity_scale, "fraction of the velocity limits to use")
      ->check(CLI::Range(1e-3, 1.0))->capture_default_str();
  sub->add_option("--acceleration-scale", o->acceleration_scale, "fraction of the acceleration and jerk limits to use")
      ->check(CLI::Range(1e-3, 1.0))->capture_default_str();
  sub->add_option("--blend", o->blend, "joint-space length of the blends at pass-through waypoints (rad)")
      ->check(CLI::Range(1e-4, 1.0))->capture_default_str();
  sub->add_flag("--json", o->json, "print one JSON object on stdout");
  add_data_dir_option(*sub, o->data_dir);
  return {sub, [o] { return run_export(*o); }};
}

}  // namespace demoplan::cli
