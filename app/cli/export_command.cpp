// demoplan-cli export: the export job (time the path within the robot's limits, check it
// independently, write the program) on a path file, then the program's files to disk.
#include <algorithm>
#include <iostream>
#include <memory>

#include <nlohmann/json.hpp>

#include "app/cli/command.h"
#include "app/cli/task_inputs.h"
#include "core/demo/benchmark_scene.h"
#include "core/error.h"
#include "core/export/export_job.h"
#include "core/export/program_writers.h"

namespace demoplan::cli {

namespace {

struct ExportCommandOptions {
  std::string path_file, robot, format, out, data_dir, cell;
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
  // The blends cut the path's corners and are checked against the path's scene.
  if (path.task.empty() && o.cell.empty())
    throw InputError(o.path_file, "task", "is empty: the scene is needed to check the blends (a cell's path: give --cell)");
  const std::shared_ptr<const Scene> scene_ptr =
      o.cell.empty() ? std::make_shared<const Scene>(build_benchmark_scene(load_benchmark_task(o.data_dir, path.task), robot, path.robot_pose))
                     : load_cell_scene(o.cell, o.data_dir);
  const Scene& scene = *scene_ptr;

  ExportSettings settings;
  settings.format = o.format;
  settings.velocity_scale = o.velocity_scale;
  settings.acceleration_scale = o.acceleration_scale;
  settings.blend = o.blend;
  settings.rate = o.rate;
  settings.gripper_output = o.gripper_output;
  settings.gripper_open_output = o.gripper_open_output;
  settings.servoj = o.servoj;
  settings.krl_ptp = o.krl_ptp;
  // A bundled mobile robot's base joints; a user's URDF names its own robot.
  const auto bundled = list_benchmark_robots(o.data_dir);
  if (std::find(bundled.begin(), bundled.end(), robot) != bundled.end())
    settings.base_joints = benchmark_base_joints(o.data_dir, robot);
  settings.source = o.path_file;
  settings.file = o.out;
  const ExportReport r = run_export_job(scene, path, settings);
  if (r.check_ok) write_program_files(r.files);

  std::vector<std::string> files;
  for (const ProgramFile& f : r.files) files.push_back(f.name);
  std::cerr << "export " << o.format << " for " << robot << " from " << o.path_file << "\n"
            << "  waypoints            " << r.waypoints << " (" << r.rests << " rests)\n"
            << "  duration             " << r.duration_s << " s\n"
            << "  trapezoid duration   " << r.trapezoid_duration_s << " s (ratio " << r.trapezoid_ratio << ")\n"
            << "  peak velocity        " << r.peak_velocity_ratio << " of the limit\n"
            << "  peak acceleration    " << r.peak_acceleration_ratio << " of the limit\n"
            << "  samples checked      " << r.samples_checked << " at " << r.rate_hz << " Hz: "
            << (r.check_ok ? "ok" : "FAILED: " + r.violations.front()) << "\n"
            << "  blends               " << r.blends << " collision-free"
            << (r.rests_added == 0 ? std::string()
                                   : "; " + std::to_string(r.rests_added) + " more rest(s) where a blend would touch the scene")
            << "\n";
  for (const auto& f : files) std::cerr << "  wrote                " << f << "\n";
  for (const auto& w : r.warnings) std::cerr << "  warning              " << w << "\n";
  if (o.json) {
    nlohmann::json j{{"format", o.format},
                     {"robot", robot},
                     {"path", o.path_file},
                     {"waypoints", r.waypoints},
                     {"rests", r.rests},
                     {"duration_s", r.duration_s},
                     {"trapezoid_duration_s", r.trapezoid_duration_s},
                     {"trapezoid_ratio", r.trapezoid_ratio},
                     {"samples", r.samples_checked},
                     {"rate_hz", r.rate_hz},
                     {"streamed_samples", r.streamed_samples},
                     {"peak_velocity_ratio", r.peak_velocity_ratio},
                     {"peak_acceleration_ratio", r.peak_acceleration_ratio},
                     {"peak_jerk_ratio", r.peak_jerk_ratio},
                     {"max_path_deviation", r.max_path_deviation},
                     {"check_ok", r.check_ok},
                     {"blends", r.blends},
                     {"rests_added_for_clearance", r.rests_added},
                     {"violations", r.violations},
                     {"files", files},
                     {"warnings", r.warnings}};
    std::cout << j.dump() << std::endl;
  }
  return r.check_ok ? kOk : kFailed;
}

// Help texts from the registry, so that a new format shows up by itself.
std::string format_choices() {
  const auto ids = program_format_ids();
  std::string s;
  for (size_t i = 0; i < ids.size(); ++i) s += (i == 0 ? "" : i + 1 == ids.size() ? " or " : ", ") + ids[i];
  return s;
}

std::string file_name_examples() {
  std::string s;
  for (const ProgramWriter* w : program_writers())
    s += (s.empty() ? "" : ", ") + w->id() + ": " + w->file_name("name");
  return s;
}

}  // namespace

Command register_export_command(CLI::App& app) {
  auto o = std::make_shared<ExportCommandOptions>();
  CLI::App* sub = app.add_subcommand("export", "time a planned path within the robot's limits and write it as a robot program");
  sub->add_option("path", o->path_file, "path JSON (demoplan-path)")->required()->check(CLI::ExistingFile);
  sub->add_option("--robot", o->robot, "robot name from robots.json (default: the path's)");
  sub->add_option("--cell", o->cell, "the cell the path was planned in (docs/cell.md), for a cell's path");
  sub->add_option("--format", o->format, format_choices())->required()->check(CLI::IsMember(program_format_ids()));
  sub->add_option("--out", o->out, "file to write (" + file_name_examples() + "; krl writes NAME.dat beside NAME.src)")
      ->required();
  sub->add_option("--rate", o->rate,
                  "Hz of sampled output (URScript servoj: 125 or 500), at which the trajectory is also checked; default " +
                      default_rates_text())
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
