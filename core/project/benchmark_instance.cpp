#include "core/project/benchmark_instance.h"

namespace demoplan {

BenchmarkInstance make_benchmark_instance(const BenchmarkTask& task, std::shared_ptr<const Scene> scene,
                                          PoseSource source) {
  DeckPlacement placed = place_on_deck(*scene, demonstration_from_benchmark(task, *scene, source));
  ValidationTask validation =
      source == PoseSource::Raw ? validation_task(placed.demonstration, *scene) : validation_task(task, *scene);
  BenchmarkInstance out;
  out.problem = make_planning_problem(std::move(scene), placed.demonstration, std::move(validation));
  out.demonstration = std::move(placed.demonstration);
  out.deck = std::move(placed.report);
  return out;
}

BenchmarkInstance make_benchmark_instance(std::shared_ptr<const Scene> scene, Demonstration demonstration) {
  DeckPlacement placed = place_on_deck(*scene, std::move(demonstration));
  ValidationTask validation = validation_task(placed.demonstration, *scene);
  BenchmarkInstance out;
  out.problem = make_planning_problem(std::move(scene), placed.demonstration, std::move(validation));
  out.demonstration = std::move(placed.demonstration);
  out.deck = std::move(placed.report);
  return out;
}

}  // namespace demoplan
