#pragma once
// A benchmark task for one robot and base pose as the planners take it: its demonstration (the
// cleaned key poses or the raw video estimates), parts that ride on the robot placed on its deck,
// and the validation task a path is judged by (the benchmark's own start and goal for key poses,
// the estimates' for raw). The one way the CLI, the benchmarks and the tests make it.
#include <memory>

#include "core/demo/benchmark_demonstration.h"
#include "core/placement/deck_placement.h"
#include "core/planning/planning_problem.h"

namespace demoplan {

struct BenchmarkInstance {
  PlanningProblem problem;
  Demonstration demonstration;  // deck placement done
  DeckPlacementReport deck;
};

// Throws InputError when the demonstration cannot be planned (naming the event).
BenchmarkInstance make_benchmark_instance(const BenchmarkTask& task, std::shared_ptr<const Scene> scene,
                                          PoseSource source);
// From a demonstration made another way (from the raw poses): judged by its own start and goal.
BenchmarkInstance make_benchmark_instance(std::shared_ptr<const Scene> scene, Demonstration demonstration);

}  // namespace demoplan
