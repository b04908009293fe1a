// demoplan-cli validate: the benchmark's success check and metrics on a saved path.
#include <iostream>
#include <memory>

#include <nlohmann/json.hpp>

#include "app/cli/command.h"
#include "app/cli/task_inputs.h"
#include "core/error.h"
#include "core/validation/path_validator.h"

namespace demoplan::cli {

namespace {

struct ValidateOptions {
  std::string path_file;
  TaskInputs inputs;
  bool json = false;
};

int run_validate(const ValidateOptions& o) {
  const Path path = load_path(o.path_file);
  // A benchmark task's path is judged against the task's own start and goal; a cell's (or a
  // given demonstration's) against the demonstration's.
  const bool by_demo = !o.inputs.cell.empty() || !o.inputs.demo.empty();
  const LoadedTask t = by_demo ? load_task_inputs(o.inputs) : LoadedTask{load_benchmark_task(o.inputs.data_dir, o.inputs.task), {}};
  const std::shared_ptr<const Scene> scene_ptr =
      by_demo ? t.instance.problem.scene
              : benchmark_scene_with_handles(t.task, o.inputs.robot, o.inputs.pose, o.inputs.handles, nullptr);
  const Scene& scene = *scene_ptr;
  const std::string what = by_demo ? (o.inputs.cell.empty() ? o.inputs.demo : o.inputs.cell) : o.inputs.task;
  if (path.joint_names.size() != static_cast<size_t>(scene.robot.model.nq))
    throw InputError(o.path_file, "joint_names", "has " + std::to_string(path.joint_names.size()) + " joints, " +
                                                     scene.robot.name + " has " + std::to_string(scene.robot.model.nq));
  for (size_t i = 0; i < scene.objects.size() && i < path.object_ids.size(); ++i)
    if (path.object_ids[i] != scene.objects[i].id || path.object_ids.size() != scene.objects.size())
      throw InputError(o.path_file, "object_ids", "do not match the objects of " + what);
  const ValidationReport v =
      validate_path(scene, by_demo ? t.instance.problem.validation : validation_task(t.task, scene), path);
  std::cerr << o.path_file << " on " << scene.name << ": " << (v.valid ? "valid" : "INVALID: " + v.message)
            << "\n  length: robot " << v.length.robot << " rad, objects " << v.length.object_translation << " m / "
            << v.length.object_rotation << " rad; " << describe_grasps(v.grasps, v.gripper_closes) << "; " << v.samples
            << " samples\n";
  nlohmann::json grasps = nlohmann::json::array();
  for (const auto& g : v.counted_grasps) {
    std::cerr << "  grasp at t = " << g.t << ": " << g.object << " by " << g.handle << "\n";
    grasps.push_back({{"t", g.t}, {"object", g.object}, {"handle", g.handle}});
  }
  if (o.json)
    std::cout << nlohmann::json{{"valid", v.valid},
                                {"message", v.message},
                                {"failure_t", v.failure_t},
                                {"path_length", {{"robot_rad", v.length.robot},
                                                 {"object_m", v.length.object_translation},
                                                 {"object_rad", v.length.object_rotation}}},
                                {"grasps", v.grasps},
                                {"gripper_closes", v.gripper_closes},
                                {"counted_grasps", grasps},
                                {"samples", v.samples}}
                     .dump()
              << std::endl;
  return v.valid ? kOk : kFailed;
}

}  // namespace

Command register_validate_command(CLI::App& app) {
  auto opts = std::make_shared<ValidateOptions>();
  CLI::App* sub = app.add_subcommand("validate", "check a path with the benchmark's rules and measure it");
  sub->add_option("path", opts->path_file, "path JSON written by plan --out")->required()->check(CLI::ExistingFile);
  add_task_inputs(*sub, opts->inputs, false);
  sub->add_flag("--json", opts->json, "print one JSON object on stdout");
  return {sub, [opts] { return run_validate(*opts); }};
}

}  // namespace demoplan::cli
