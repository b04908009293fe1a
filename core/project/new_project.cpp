#include "core/project/new_project.h"

#include "core/demo/benchmark_demonstration.h"
#include "core/demo/benchmark_scene.h"

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

}  // namespace demoplan
