#include "core/project/benchmark_instance.h"

namespace demoplan {

namespace {

// Parts on the deck placed, then the problem judged by `validation` (made from the placed
// demonstration, or the task's own key poses when it is null).
BenchmarkInstance assemble(std::shared_ptr<const Scene> scene, Demonstration demonstration, const BenchmarkTask* task) {
  DeckPlacement placed = place_on_deck(*scene, std::move(demonstration));
  ValidationTask validation = task ? validation_task(*task, *scene) : validation_task(placed.demonstration, *scene);
  BenchmarkInstance out;
  out.problem = make_planning_problem(std::move(scene), placed.demonstration, std::move(validation));
  out.demonstration = std::move(placed.demonstration);
  out.deck = std::move(placed.report);
  return out;
}

}  // namespace

BenchmarkInstance make_benchmark_instance(const BenchmarkTask& task, std::shared_ptr<const Scene> scene,
                                          PoseSource source) {
  Demonstration demonstration = demonstration_from_benchmark(task, *scene, source);
  return assemble(std::move(scene), std::move(demonstration), source == PoseSource::Raw ? nullptr : &task);
}

BenchmarkInstance make_benchmark_instance(std::shared_ptr<const Scene> scene, Demonstration demonstration) {
  return assemble(std::move(scene), std::move(demonstration), nullptr);
}

}  // namespace demoplan
