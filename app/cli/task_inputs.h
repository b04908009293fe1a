#pragma once
// The options every task-level subcommand shares (--task, --robot, --pose, --from, --data-dir)
// and what they load.
#include <string>

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
};

struct LoadedTask {
  BenchmarkTask task;
  BenchmarkInstance instance;
  const Scene& scene() const { return *instance.problem.scene; }
  const Demonstration& demo() const { return instance.demonstration; }
};

void add_task_inputs(CLI::App& sub, TaskInputs& inputs, bool with_from = true);
// --from: where the object poses (and, for tracks, the events) come from.
void add_from_option(CLI::App& sub, std::string& from);
// The task instance for `from`: the cleaned key poses (subgoals), the raw estimates at the
// labelled events (raw), or events and poses from the raw estimates alone (tracks; what the
// detection could not decide is printed on stderr).
BenchmarkInstance make_task_instance(const BenchmarkTask& task, std::shared_ptr<const Scene> scene, const std::string& from);
LoadedTask load_task_inputs(const TaskInputs& inputs);

}  // namespace demoplan::cli
