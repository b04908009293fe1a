#include "app/cli/task_inputs.h"

#include <iostream>

#include "core/demo/benchmark_demonstration.h"
#include "core/placement/deck_placement.h"

namespace demoplan::cli {

void add_task_inputs(CLI::App& sub, TaskInputs& in, bool with_from) {
  sub.add_option("--task", in.task, "task as <task>_<demo>, e.g. shelf_1")->capture_default_str();
  sub.add_option("--robot", in.robot, "robot name from robots.json: panda, ur5, kmr_iiwa")->capture_default_str();
  sub.add_option("--pose", in.pose, "robot base pose id of the task")->capture_default_str();
  if (with_from)
    sub.add_option("--from", in.from, "object poses from the cleaned key poses or the raw video estimates")
        ->check(CLI::IsMember({"raw", "subgoals"}))
        ->capture_default_str();
  add_data_dir_option(sub, in.data_dir);
}

LoadedTask load_task_inputs(const TaskInputs& in) {
  LoadedTask t{load_benchmark_task(in.data_dir, in.task), {}};
  t.instance = make_benchmark_instance(t.task, std::make_shared<const Scene>(build_benchmark_scene(t.task, in.robot, in.pose)),
                                       in.from == "raw" ? PoseSource::Raw : PoseSource::Subgoals);
  // Objects riding on the robot: say where they were put when it is not where the demonstrator
  // put them.
  const DeckPlacementReport& deck = t.instance.deck;
  if (!deck.rests.empty()) {
    std::cerr << "deck poses chosen in " << static_cast<int>(deck.seconds * 1000) << " ms:\n";
    for (const auto& note : deck.notes()) std::cerr << "  " << note << "\n";
  }
  return t;
}

}  // namespace demoplan::cli
