#pragma once
// The options every task-level subcommand shares (--task, --robot, --pose, --from, --data-dir)
// and what they load.
#include <string>

#include <nlohmann/json.hpp>

#include "app/cli/command.h"
#include "core/demo/benchmark_scene.h"
#include "core/project/benchmark_instance.h"

namespace demoplan::cli {

struct TaskInputs {
  std::string task = "shelf_1";
  std::string robot = "panda";
  int pose = 0;
  std::string from = "subgoals";  // raw | subgoals | tracks
  std::string data_dir;
  std::string cell;  // a cell file in place of the benchmark task, robot and pose
  std::string demo;  // a demonstration file: required with a cell, in place of --from for a task
  std::string handles = "srdf";  // srdf | generated: the parts' handles, hand-made or generated
};

struct LoadedTask {
  BenchmarkTask task;  // empty for a cell
  BenchmarkInstance instance;
  const Scene& scene() const { return *instance.problem.scene; }
  const Demonstration& demo() const { return instance.demonstration; }
};

void add_task_inputs(CLI::App& sub, TaskInputs& inputs, bool with_from = true);
// What the inputs name, for a command's JSON: task, robot, pose and from, or cell and demo.
nlohmann::json describe_inputs(const TaskInputs& inputs);
// --from: where the object poses (and, for tracks, the events) come from.
CLI::Option* add_from_option(CLI::App& sub, std::string& from);
// The task instance for `from`: the cleaned key poses (subgoals), the raw estimates at the
// labelled events (raw), or events and poses from the raw estimates alone (tracks; what the
// detection could not decide is printed on stderr).
BenchmarkInstance make_task_instance(const BenchmarkTask& task, std::shared_ptr<const Scene> scene, const std::string& from);
LoadedTask load_task_inputs(const TaskInputs& inputs);
// --handles: the benchmark parts' hand-made SRDF handles, or handles generated from their meshes.
CLI::Option* add_handles_option(CLI::App& sub, std::string& handles);
// The benchmark scene with `handles` applied (generated: each part's handles replaced).
std::shared_ptr<const Scene> benchmark_scene_with_handles(const BenchmarkTask& task, const std::string& robot, int pose,
                                                          const std::string& handles, MeshCache* meshes = nullptr);
// The scene of a cell file, its generated handles and placements summed up on stderr.
std::shared_ptr<const Scene> load_cell_scene(const std::string& file, const std::string& data_dir);
// A cell's task instance: the demonstration file's parts settled onto the cell's supports (a
// demonstration from video rests them a millimetre off); a part resting on no support is refused
// naming the event (settle_for_planning).
BenchmarkInstance cell_task_instance(std::shared_ptr<const Scene> scene, const std::string& demo_file);

}  // namespace demoplan::cli
