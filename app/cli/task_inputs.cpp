#include "app/cli/task_inputs.h"

#include <iostream>

#include "core/demo/benchmark_demonstration.h"
#include "core/placement/deck_placement.h"
#include "perception/events/tracks_demonstration.h"

namespace demoplan::cli {

void add_task_inputs(CLI::App& sub, TaskInputs& in, bool with_from) {
  sub.add_option("--task", in.task, "task as <task>_<demo>, e.g. shelf_1")->capture_default_str();
  sub.add_option("--robot", in.robot, "robot name from robots.json: panda, ur5, kmr_iiwa")->capture_default_str();
  sub.add_option("--pose", in.pose, "robot base pose id of the task")->capture_default_str();
  if (with_from) add_from_option(sub, in.from);
  add_data_dir_option(sub, in.data_dir);
}

void add_from_option(CLI::App& sub, std::string& from) {
  sub.add_option("--from", from,
                 "the demonstration from the cleaned key poses (subgoals), the raw video estimates at the "
                 "labelled contacts (raw), or events and poses from the raw estimates alone (tracks)")
      ->check(CLI::IsMember({"raw", "subgoals", "tracks"}))
      ->capture_default_str();
}

BenchmarkInstance make_task_instance(const BenchmarkTask& task, std::shared_ptr<const Scene> scene, const std::string& from) {
  if (from != "tracks") return make_benchmark_instance(task, std::move(scene), from == "raw" ? PoseSource::Raw : PoseSource::Subgoals);
  perception::TracksDemonstration found = perception::demonstration_from_tracks(task, *scene);
  for (const auto& d : found.demonstration.doubts)
    std::cerr << task.name() << ": frames " << d.first_frame << "-" << d.last_frame << ": " << d.message << "\n";
  return make_benchmark_instance(std::move(scene), std::move(found.demonstration));
}

LoadedTask load_task_inputs(const TaskInputs& in) {
  LoadedTask t{load_benchmark_task(in.data_dir, in.task), {}};
  t.instance = make_task_instance(t.task, std::make_shared<const Scene>(build_benchmark_scene(t.task, in.robot, in.pose)), in.from);
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
