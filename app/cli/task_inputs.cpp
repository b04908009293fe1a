#include "app/cli/task_inputs.h"

#include <iostream>

#include "core/cell/cell_scene.h"
#include "core/demo/supported_rests.h"
#include "core/demo/benchmark_demonstration.h"
#include "core/error.h"
#include "core/part/grasp_handles.h"
#include "core/scene/collision_checker.h"
#include "core/placement/deck_placement.h"
#include "perception/events/tracks_demonstration.h"

namespace demoplan::cli {

void add_task_inputs(CLI::App& sub, TaskInputs& in, bool with_from) {
  auto* task = sub.add_option("--task", in.task, "task as <task>_<demo>, e.g. shelf_1")->capture_default_str();
  auto* robot = sub.add_option("--robot", in.robot, "robot name from robots.json: panda, ur5, kmr_iiwa")->capture_default_str();
  auto* pose = sub.add_option("--pose", in.pose, "robot base pose id of the task")->capture_default_str();
  auto* cell = sub.add_option("--cell", in.cell, "a cell file (docs/cell.md) in place of --task, --robot and --pose");
  cell->excludes(task)->excludes(robot)->excludes(pose);
  auto* demo = sub.add_option("--demo", in.demo, "a demonstration file (required with --cell; for a task, in place of --from)");
  if (with_from) {
    CLI::Option* from = add_from_option(sub, in.from);
    cell->excludes(from);
    demo->excludes(from);
  }
  add_handles_option(sub, in.handles)->excludes(cell);
  add_data_dir_option(sub, in.data_dir);
}

CLI::Option* add_handles_option(CLI::App& sub, std::string& handles) {
  return sub
      .add_option("--handles", handles,
                  "the parts' grasp handles: the benchmark's hand-made ones (srdf) or generated from the parts' meshes "
                  "for the robot's gripper (generated)")
      ->check(CLI::IsMember({"srdf", "generated"}))
      ->capture_default_str();
}

std::shared_ptr<const Scene> benchmark_scene_with_handles(const BenchmarkTask& task, const std::string& robot, int pose,
                                                          const std::string& handles, MeshCache* meshes) {
  Scene scene = build_benchmark_scene(task, robot, pose, {.mesh_cache = meshes});
  if (handles == "generated") {
    const ParallelGripper gripper = parallel_gripper(scene.robot.model, scene.robot.srdf);
    for (SceneObject& o : scene.objects) use_generated_handles(o, gripper);
  }
  return std::make_shared<const Scene>(std::move(scene));
}

nlohmann::json describe_inputs(const TaskInputs& in) {
  if (!in.cell.empty()) return {{"cell", in.cell}, {"demo", in.demo}};
  nlohmann::json j{{"task", in.task}, {"robot", in.robot}, {"pose", in.pose}, {"handles", in.handles}};
  if (!in.demo.empty()) j["demo"] = in.demo;
  else j["from"] = in.from;
  return j;
}

CLI::Option* add_from_option(CLI::App& sub, std::string& from) {
  return sub.add_option("--from", from,
                 "the demonstration from the cleaned key poses (subgoals), the raw video estimates at the "
                 "labelled contacts (raw), or events and poses from the raw estimates alone (tracks)")
      ->check(CLI::IsMember({"raw", "subgoals", "tracks"}))
      ->capture_default_str();
}

std::shared_ptr<const Scene> load_cell_scene(const std::string& file, const std::string& data_dir) {
  const Cell cell = load_cell(file);
  CellSceneReport report;
  auto scene = std::make_shared<const Scene>(build_cell_scene(cell, {.data_dir = data_dir}, &report));
  for (const auto& p : report.parts)
    if (p.generated)
      std::cerr << cell.name << ": " << p.part << ": " << p.grasps.handles.size() << " handles generated in "
                << static_cast<int>(p.grasps.seconds * 1000) << " ms, " << p.placements << " resting placements\n";
  // A cell that starts in collision cannot be planned in: say so before anything is sampled.
  const CollisionChecker checker(*scene);
  CollisionData data = checker.make_data();
  CollisionPair hit;
  if (checker.in_collision(cell_start_state(cell, *scene), data, {}, &hit))
    throw InputError(file, hit.first.rfind("robot", 0) == 0 || hit.second.rfind("robot", 0) == 0 ? "robot" : "parts",
                     "the cell starts in collision: " + hit.first + " / " + hit.second);
  return scene;
}

BenchmarkInstance cell_task_instance(std::shared_ptr<const Scene> scene, const std::string& demo_file) {
  Demonstration demo = settle_for_planning(*scene, load_demonstration(demo_file), demo_file);
  return make_benchmark_instance(std::move(scene), std::move(demo));
}

BenchmarkInstance make_task_instance(const BenchmarkTask& task, std::shared_ptr<const Scene> scene, const std::string& from) {
  if (from != "tracks") return make_benchmark_instance(task, std::move(scene), from == "raw" ? PoseSource::Raw : PoseSource::Subgoals);
  perception::TracksDemonstration found = perception::demonstration_from_tracks(task, *scene);
  for (const auto& d : found.demonstration.doubts)
    std::cerr << task.name() << ": frames " << d.first_frame << "-" << d.last_frame << ": " << d.message << "\n";
  return make_benchmark_instance(std::move(scene), std::move(found.demonstration));
}

LoadedTask load_task_inputs(const TaskInputs& in) {
  LoadedTask t;
  if (!in.cell.empty()) {
    if (in.demo.empty()) throw InputError(in.cell, "", "a cell needs a demonstration: give --demo");
    t.instance = cell_task_instance(load_cell_scene(in.cell, in.data_dir), in.demo);
    return t;
  }
  t.task = load_benchmark_task(in.data_dir, in.task);
  auto scene = benchmark_scene_with_handles(t.task, in.robot, in.pose, in.handles);
  t.instance = in.demo.empty() ? make_task_instance(t.task, std::move(scene), in.from)
                               : make_benchmark_instance(std::move(scene), settle_for_planning(*scene, load_demonstration(in.demo), in.demo));
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
