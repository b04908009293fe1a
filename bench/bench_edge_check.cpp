// Edge collision checks in the planner's order (StateValidity::segment_free: bisection, stop at
// the first collision) against a walk from one end to the other, on the same edges of Panda
// shelf_2 (issue 19, item 3), drawn where the planner works: near a path it found. Planner
// edges: 0.3 rad from a waypoint to a collision-free configuration, checked every 0.005 rad;
// shortcut edges: straight cuts between two waypoints of one run of a state, every 0.0025 rad.
#include <benchmark/benchmark.h>

#include <cmath>
#include <random>

#include "core/demo/benchmark_scene.h"
#include "core/graph/state_validity.h"
#include "core/planning/guided_planner.h"
#include "core/project/benchmark_instance.h"

using namespace demoplan;

namespace {

struct Edge {
  int state;
  Eigen::VectorXd a, b;
};

struct Fixture {
  BenchmarkTask task = load_benchmark_task(DEMOPLAN_DATA_DIR, "shelf_2");
  PlanningProblem problem = make_benchmark_instance(
      task, std::make_shared<const Scene>(build_benchmark_scene(task, "panda", 0)), PoseSource::Subgoals).problem;
  std::vector<Edge> planner_edges, shortcut_edges;

  Fixture() {
    const auto& m = problem.scene->robot.model;
    const Eigen::VectorXd lo = m.lower_limits(), hi = m.upper_limits();
    const StateValidity validity(*problem.scene, *problem.graph, *problem.checker);
    CollisionData data = problem.checker->make_data();
    PlannerParams params;
    params.seed = 1;
    const std::vector<Waypoint> w = GuidedPlanner(params).solve(problem, StopCondition(60.0, nullptr), {}).path.waypoints;
    std::mt19937_64 rng(1);
    std::uniform_real_distribution<double> u(0, 1);
    auto pick = [&] { return std::uniform_int_distribution<size_t>(0, w.size() - 1)(rng); };
    // Both ends free, as the planner and the shortcut check the ends before the edge.
    while (planner_edges.size() < 512) {
      const Waypoint& a = w[pick()];
      Eigen::VectorXd d(m.nq);
      for (int k = 0; k < m.nq; ++k) d[k] = u(rng) - 0.5;
      const Eigen::VectorXd b = (a.q + d.normalized() * 0.3).cwiseMax(lo).cwiseMin(hi);
      if (validity.configuration_free(a.state, b, data)) planner_edges.push_back({a.state, a.q, b});
    }
    for (int tries = 0; shortcut_edges.size() < 512 && tries < 100000; ++tries) {
      size_t i = pick(), j = pick();
      if (i > j) std::swap(i, j);
      bool one_run = j > i + 1;
      for (size_t k = i; k <= j && one_run; ++k) one_run = w[k].state == w[i].state;
      if (one_run) shortcut_edges.push_back({w[i].state, w[i].q, w[j].q});
    }
  }
};

Fixture& fixture() {
  static Fixture f;
  return f;
}

// The samples of segment_free in order from a to b.
bool walk_free(const PlanningProblem& p, const Edge& e, double resolution, CollisionData& data) {
  const int steps = static_cast<int>(std::ceil((e.b - e.a).norm() / resolution));
  SceneState s = scene_state(*p.scene, *p.graph, e.state, e.a);
  for (int k = 1; k < steps; ++k) {
    s.q = e.a + (e.b - e.a) * (static_cast<double>(k) / steps);
    if (p.checker->in_collision(s, data)) return false;
  }
  return true;
}

void edge_check(benchmark::State& st, bool bisection, bool shortcut) {
  Fixture& f = fixture();
  const std::vector<Edge>& edges = shortcut ? f.shortcut_edges : f.planner_edges;
  const double resolution = shortcut ? 0.0025 : 0.005;
  const StateValidity validity(*f.problem.scene, *f.problem.graph, *f.problem.checker, resolution);
  CollisionData data = f.problem.checker->make_data();
  size_t i = 0, colliding = 0;
  for (auto _ : st) {
    const Edge& e = edges[i++ % edges.size()];
    colliding += !(bisection ? validity.segment_free(e.state, e.a, e.b, data) : walk_free(f.problem, e, resolution, data));
  }
  st.counters["edges_per_s"] = benchmark::Counter(static_cast<double>(st.iterations()), benchmark::Counter::kIsRate);
  st.counters["colliding_fraction"] = static_cast<double>(colliding) / static_cast<double>(st.iterations());
}

}  // namespace

BENCHMARK_CAPTURE(edge_check, planner_walk, false, false)->Unit(benchmark::kMicrosecond)->MinTime(1.0);
BENCHMARK_CAPTURE(edge_check, planner_bisection, true, false)->Unit(benchmark::kMicrosecond)->MinTime(1.0);
BENCHMARK_CAPTURE(edge_check, shortcut_walk, false, true)->Unit(benchmark::kMicrosecond)->MinTime(1.0);
BENCHMARK_CAPTURE(edge_check, shortcut_bisection, true, true)->Unit(benchmark::kMicrosecond)->MinTime(1.0);

BENCHMARK_MAIN();
