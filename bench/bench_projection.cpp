// Constraint projection: successful transition samples per second (IK onto the handle plus
// the straight approach), one thread. Target (issue 3): >= 5,000/s for Panda.
#include <benchmark/benchmark.h>

#include "core/demo/benchmark_demonstration.h"
#include "core/demo/benchmark_scene.h"
#include "core/graph/projector.h"

using namespace demoplan;

namespace {

void transition_sampling(benchmark::State& st, const std::string& task_name, const std::string& robot) {
  const BenchmarkTask task = load_benchmark_task(DEMOPLAN_DATA_DIR, task_name);
  const Scene scene = build_benchmark_scene(task, robot, 0);
  const ConstraintGraph graph = build_constraint_graph(scene, demonstration_from_subgoals(task));
  const ConstraintProjector projector(scene, graph);
  std::mt19937_64 rng(1);
  long ok = 0, n = 0, iterations = 0;
  for (auto _ : st) {
    const auto s = projector.sample_on_transition(static_cast<int>(n++ % graph.transitions.size()), rng);
    ok += s.ok;
    iterations += s.ik_iterations;
  }
  st.counters["ik_iterations"] = static_cast<double>(iterations) / n;
  st.counters["successful_per_s"] = benchmark::Counter(static_cast<double>(ok), benchmark::Counter::kIsRate);
  st.counters["success_rate"] = static_cast<double>(ok) / n;
}

void projection(benchmark::State& st, const std::string& task_name, const std::string& robot) {
  const BenchmarkTask task = load_benchmark_task(DEMOPLAN_DATA_DIR, task_name);
  const Scene scene = build_benchmark_scene(task, robot, 0);
  const ConstraintGraph graph = build_constraint_graph(scene, demonstration_from_subgoals(task));
  const ConstraintProjector projector(scene, graph);
  std::mt19937_64 rng(1);
  long ok = 0, n = 0;
  for (auto _ : st) {
    const int t = static_cast<int>(n++ % graph.transitions.size());
    ok += projector.project(t, projector.sample_configuration(graph.transitions[t].from, rng), rng).success;
  }
  st.counters["successful_per_s"] = benchmark::Counter(static_cast<double>(ok), benchmark::Counter::kIsRate);
  st.counters["success_rate"] = static_cast<double>(ok) / n;
}

}  // namespace

BENCHMARK_CAPTURE(projection, panda_shelf_1, std::string("shelf_1"), std::string("panda"))->Unit(benchmark::kMicrosecond)->MinTime(2.0);
BENCHMARK_CAPTURE(projection, ur5_shelf_1, std::string("shelf_1"), std::string("ur5"))->Unit(benchmark::kMicrosecond)->MinTime(2.0);
BENCHMARK_CAPTURE(projection, kmr_iiwa_shelf_1, std::string("shelf_1"), std::string("kmr_iiwa"))->Unit(benchmark::kMicrosecond)->MinTime(2.0);
BENCHMARK_CAPTURE(transition_sampling, panda_shelf_1, std::string("shelf_1"), std::string("panda"))->Unit(benchmark::kMicrosecond)->MinTime(2.0);
BENCHMARK_CAPTURE(transition_sampling, ur5_shelf_1, std::string("shelf_1"), std::string("ur5"))->Unit(benchmark::kMicrosecond)->MinTime(2.0);
BENCHMARK_CAPTURE(transition_sampling, kmr_iiwa_shelf_1, std::string("shelf_1"), std::string("kmr_iiwa"))->Unit(benchmark::kMicrosecond)->MinTime(2.0);

BENCHMARK_MAIN();
