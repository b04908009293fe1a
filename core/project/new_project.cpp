#include "core/project/new_project.h"

#include "core/demo/benchmark_demonstration.h"
#include "core/cell/cell_scene.h"
#include "core/demo/benchmark_scene.h"
#include "core/error.h"

namespace demoplan {

NewProject new_benchmark_project(const std::string& data_dir, const SceneReference& ref, const StopCondition& stop,
                                 const DeckPlacementProgress& progress) {
  const BenchmarkTask task = load_benchmark_task(data_dir, ref.task);
  const Scene scene = build_benchmark_scene(task, ref.robot, ref.pose);
  DeckPlacement placed =
      place_on_deck(scene, demonstration_from_benchmark(task, scene, PoseSource::Subgoals), {}, stop, progress);
  NewProject out;
  out.project.scene = ref;
  out.project.demonstration = std::move(placed.demonstration);
  out.deck = std::move(placed.report);
  return out;
}

NewProject new_cell_project(const std::string& data_dir, const std::string& cell_file, const Demonstration* given,
                            const StopCondition& stop, const DeckPlacementProgress& progress) {
  const Cell cell = load_cell(cell_file);
  const Scene scene = build_cell_scene(cell, {.data_dir = data_dir});
  NewProject out;
  out.project.scene.cell = cell.file;
  if (!given) {
    Demonstration& d = out.project.demonstration;
    d.task = scene.name;
    for (const auto& o : scene.objects) d.object_ids.push_back(o.id);
    return out;
  }
  std::vector<std::string> ids;
  for (const auto& o : scene.objects) ids.push_back(o.id);
  if (given->object_ids != ids)
    throw InputError(cell_file, "parts", "are not the objects the demonstration lists, in its order");
  DeckPlacement placed = place_on_deck(scene, *given, {}, stop, progress);
  out.project.demonstration = std::move(placed.demonstration);
  out.deck = std::move(placed.report);
  return out;
}

}  // namespace demoplan
