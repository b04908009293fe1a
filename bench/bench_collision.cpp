// Full-scene collision checks per second on random configurations, one thread.
// Target (issue 2): >= 10,000 checks/s for Panda in the largest shelf scene (shelf_2).
#include <benchmark/benchmark.h>

#include <random>

#include "core/demo/benchmark_scene.h"
#include "core/scene/collision_checker.h"

using namespace demoplan;

namespace {

struct Fixture {
  BenchmarkTask task;
  Scene scene;
  std::unique_ptr<CollisionChecker> checker;
  std::vector<SceneState> states;

  Fixture(const std::string& task_name, const std::string& robot, int pose)
      : task(load_benchmark_task(DEMOPLAN_DATA_DIR, task_name)),
        scene(build_benchmark_scene(task, robot, pose)),
        checker(std::make_unique<CollisionChecker>(scene)) {
    const auto& m = scene.robot.model;
    const Eigen::VectorXd lo = m.lower_limits(), hi = m.upper_limits();
    std::mt19937_64 rng(1);
    std::uniform_real_distribution<double> u(0, 1);
    for (int i = 0; i < 4096; ++i) {
      SceneState s = benchmark_start_state(task, scene);
      for (int k = 0; k < m.nq; ++k) s.q[k] = lo[k] + u(rng) * (hi[k] - lo[k]);
      states.push_back(std::move(s));
    }
  }
};

Fixture& fixture(const std::string& task, const std::string& robot) {
  static std::map<std::string, std::unique_ptr<Fixture>> cache;
  auto& f = cache[task + robot];
  if (!f) f = std::make_unique<Fixture>(task, robot, 0);
  return *f;
}

void full_scene_check(benchmark::State& st, const std::string& task, const std::string& robot) {
  Fixture& f = fixture(task, robot);
  auto data = f.checker->make_data();
  size_t i = 0, colliding = 0;
  for (auto _ : st) {
    colliding += f.checker->in_collision(f.states[i++ % f.states.size()], data);
  }
  st.counters["checks_per_s"] = benchmark::Counter(static_cast<double>(st.iterations()), benchmark::Counter::kIsRate);
  st.counters["colliding_fraction"] = static_cast<double>(colliding) / st.iterations();
}

void distance_query(benchmark::State& st) {
  Fixture& f = fixture("shelf_2", "panda");
  auto data = f.checker->make_data();
  size_t i = 0;
  for (auto _ : st) benchmark::DoNotOptimize(f.checker->distance(f.states[i++ % f.states.size()], data));
}

void build_checker(benchmark::State& st) {
  Fixture& f = fixture("shelf_2", "panda");
  for (auto _ : st) CollisionChecker c(f.scene);
}

}  // namespace

BENCHMARK_CAPTURE(full_scene_check, panda_shelf_2, std::string("shelf_2"), std::string("panda"))->MinTime(1.0);
BENCHMARK_CAPTURE(full_scene_check, ur5_shelf_2, std::string("shelf_2"), std::string("ur5"))->MinTime(1.0);
BENCHMARK_CAPTURE(full_scene_check, kmr_iiwa_shelf_2, std::string("shelf_2"), std::string("kmr_iiwa"))->MinTime(1.0);
BENCHMARK_CAPTURE(full_scene_check, kmr_iiwa_waiter_0, std::string("waiter_0"), std::string("kmr_iiwa"))->MinTime(1.0);
BENCHMARK_CAPTURE(full_scene_check, panda_tunnel_0, std::string("tunnel_0"), std::string("panda"))->MinTime(1.0);
BENCHMARK(distance_query)->Unit(benchmark::kMicrosecond);
BENCHMARK(build_checker)->Unit(benchmark::kMillisecond);

BENCHMARK_MAIN();
