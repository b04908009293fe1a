// Full-scene collision checks per second on random configurations, one thread, with the
// checker's fast path (full_scene_check) and with FCL alone (full_scene_check_fcl_alone) on the
// same configurations; side_by_side: both in turn, 256 configurations each, timed apart. The
// ratios of both kinds are printed per scene after the table. first_pass:
// one pass on a new checker (its self-pair tables and its data's remembered triangle pairs
// empty), with and without the fast path.
// Targets: >= 10,000 checks/s for Panda in the largest shelf scene, shelf_2 (issue 2); with the
// fast path >= 100,000/s there and >= 2.5 times FCL alone (issue 19).
#include <benchmark/benchmark.h>

#include <chrono>
#include <cstdio>
#include <map>
#include <random>

#include "core/demo/benchmark_scene.h"
#include "core/scene/bounding_spheres.h"
#include "core/scene/bvh_cache.h"
#include "core/scene/collision_checker.h"

#include <fcl/fcl.h>

using namespace demoplan;

namespace {

struct Fixture {
  BenchmarkTask task;
  Scene scene;
  std::unique_ptr<CollisionChecker> checker;
  std::unique_ptr<CollisionChecker> fcl_alone;  // the fast path off
  std::vector<SceneState> states;

  static CollisionOptions without_fast_path() {
    CollisionOptions o;
    o.fast_path = false;
    return o;
  }

  Fixture(const std::string& task_name, const std::string& robot, int pose)
      : task(load_benchmark_task(DEMOPLAN_DATA_DIR, task_name)),
        scene(build_benchmark_scene(task, robot, pose)),
        checker(std::make_unique<CollisionChecker>(scene)),
        fcl_alone(std::make_unique<CollisionChecker>(scene, without_fast_path())) {
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

void check_states(benchmark::State& st, const CollisionChecker& checker, const std::vector<SceneState>& states) {
  auto data = checker.make_data();
  size_t i = 0, colliding = 0;
  for (auto _ : st) {
    colliding += checker.in_collision(states[i++ % states.size()], data);
  }
  st.counters["checks_per_s"] = benchmark::Counter(static_cast<double>(st.iterations()), benchmark::Counter::kIsRate);
  st.counters["colliding_fraction"] = static_cast<double>(colliding) / st.iterations();
}

void full_scene_check(benchmark::State& st, const std::string& task, const std::string& robot) {
  Fixture& f = fixture(task, robot);
  check_states(st, *f.checker, f.states);
}

void full_scene_check_fcl_alone(benchmark::State& st, const std::string& task, const std::string& robot) {
  Fixture& f = fixture(task, robot);
  check_states(st, *f.fcl_alone, f.states);
}

// Both checkers over the same 256 configurations in turn, each batch timed on its own, for as
// long as the benchmark runs: a slow moment of a shared machine (another process, a neighbour
// on the host) falls on both alike, so their ratio holds steadier than that of two separate runs.
void side_by_side(benchmark::State& st, const std::string& task, const std::string& robot) {
  using Clock = std::chrono::steady_clock;
  Fixture& f = fixture(task, robot);
  auto fast_data = f.checker->make_data(), fcl_data = f.fcl_alone->make_data();
  constexpr size_t kBatch = 256;
  double fast_s = 0, fcl_s = 0;
  size_t next = 0, checked = 0;
  for (auto _ : st) {
    const auto t0 = Clock::now();
    for (size_t k = 0; k < kBatch; ++k)
      benchmark::DoNotOptimize(f.checker->in_collision(f.states[(next + k) % f.states.size()], fast_data));
    const auto t1 = Clock::now();
    for (size_t k = 0; k < kBatch; ++k)
      benchmark::DoNotOptimize(f.fcl_alone->in_collision(f.states[(next + k) % f.states.size()], fcl_data));
    const auto t2 = Clock::now();
    fast_s += std::chrono::duration<double>(t1 - t0).count();
    fcl_s += std::chrono::duration<double>(t2 - t1).count();
    next += kBatch;
    checked += kBatch;
  }
  st.counters["fast_per_s"] = static_cast<double>(checked) / fast_s;
  st.counters["fcl_alone_per_s"] = static_cast<double>(checked) / fcl_s;
  st.counters["ratio"] = fcl_s / fast_s;
}

// The console table, then per scene: checks/s with the fast path, with FCL alone, and the ratio.
class RatioReporter : public benchmark::ConsoleReporter {
public:
  void ReportRuns(const std::vector<Run>& runs) override {
    ConsoleReporter::ReportRuns(runs);
    for (const auto& r : runs) {
      if (r.error_occurred || r.run_type != Run::RT_Iteration) continue;
      const std::string name = r.benchmark_name();
      const std::string together = "side_by_side/";
      if (name.rfind(together, 0) == 0) {
        const std::string scene = name.substr(together.size(), name.find('/', together.size()) - together.size());
        interleaved_[scene] = {r.counters.at("fast_per_s").value, r.counters.at("fcl_alone_per_s").value};
        continue;
      }
      const auto it = r.counters.find("checks_per_s");
      if (it == r.counters.end()) continue;
      const std::string fcl = "full_scene_check_fcl_alone/", fast = "full_scene_check/";
      if (name.rfind(fcl, 0) == 0) rates_[name.substr(fcl.size())].second = it->second.value;
      else if (name.rfind(fast, 0) == 0) rates_[name.substr(fast.size())].first = it->second.value;
    }
  }
  void print_ratios() const {
    std::printf("\nseparate runs\n%-26s %14s %14s %7s\n", "scene", "fast path/s", "FCL alone/s", "ratio");
    for (const auto& [key, r] : rates_)
      if (r.first > 0 && r.second > 0) {
        const std::string scene = key.substr(0, key.find('/'));  // without "/min_time:..."
        std::printf("%-26s %14.0f %14.0f %7.2f\n", scene.c_str(), r.first, r.second, r.first / r.second);
      }
    if (interleaved_.empty()) return;
    std::printf("\nside by side (batches of 256 in turn)\n%-26s %14s %14s %7s\n", "scene", "fast path/s",
                "FCL alone/s", "ratio");
    for (const auto& [scene, r] : interleaved_)
      std::printf("%-26s %14.0f %14.0f %7.2f\n", scene.c_str(), r.first, r.second, r.first / r.second);
  }

private:
  std::map<std::string, std::pair<double, double>> rates_;  // scene (with MinTime suffix): fast, FCL
  std::map<std::string, std::pair<double, double>> interleaved_;  // scene: fast, FCL
};

// One pass over the 4096 configurations on a new checker, whose self-pair distance tables
// (joint_pair_table.h) and remembered triangle pairs (mesh_contact_witness.h) start empty: what
// a fresh process pays before they fill.
void first_pass(benchmark::State& st, const std::string& task, const std::string& robot, bool fast_path) {
  Fixture& f = fixture(task, robot);
  CollisionOptions options;
  options.fast_path = fast_path;
  for (auto _ : st) {
    st.PauseTiming();
    auto checker = std::make_unique<CollisionChecker>(f.scene, options);
    auto data = checker->make_data();
    st.ResumeTiming();
    for (const auto& s : f.states) benchmark::DoNotOptimize(checker->in_collision(s, data));
  }
  st.counters["checks_per_s"] =
      benchmark::Counter(static_cast<double>(st.iterations() * f.states.size()), benchmark::Counter::kIsRate);
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

// Fitting every mesh of a scene once on one thread, as a process's first checker does
// (bvh_cache.h; the checker spreads the meshes over the cores): the bounding spheres alone
// (ours), then FCL's OBBRSS BVHs alone.
struct ScaledMesh {
  std::vector<Eigen::Vector3d> vertices;
  const TriangleMesh* mesh;
};
std::vector<ScaledMesh> scene_meshes(const Scene& scene) {
  std::vector<ScaledMesh> out;
  for (const auto& [mesh, scale] : collision_meshes(scene)) {
    out.push_back({scaled_vertices(*mesh, scale), mesh});
  }
  return out;
}

void fit_spheres(benchmark::State& st, const std::string& task, const std::string& robot) {
  const std::vector<ScaledMesh> meshes = scene_meshes(fixture(task, robot).scene);
  for (auto _ : st)
    for (const auto& m : meshes) benchmark::DoNotOptimize(fit_bounding_spheres(m.vertices, m.mesh->triangles));
  st.counters["meshes"] = static_cast<double>(meshes.size());
}

void fit_fcl_bvhs(benchmark::State& st, const std::string& task, const std::string& robot) {
  const std::vector<ScaledMesh> meshes = scene_meshes(fixture(task, robot).scene);
  for (auto _ : st)
    for (const auto& m : meshes) {
      fcl::BVHModel<fcl::OBBRSSd> bvh;
      std::vector<fcl::Triangle> triangles;
      for (const auto& t : m.mesh->triangles) triangles.emplace_back(t[0], t[1], t[2]);
      bvh.beginModel(static_cast<int>(triangles.size()), static_cast<int>(m.vertices.size()));
      bvh.addSubModel(m.vertices, triangles);
      bvh.endModel();
      benchmark::DoNotOptimize(bvh.getNumBVs());
    }
}

}  // namespace

// Each scene with the fast path, then with FCL alone, then both in turn, on the same 4096
// configurations.
#define SCENE_BENCHMARKS(name, task, robot)                                                            \
  BENCHMARK_CAPTURE(full_scene_check, name, std::string(task), std::string(robot))->MinTime(1.0);      \
  BENCHMARK_CAPTURE(full_scene_check_fcl_alone, name, std::string(task), std::string(robot))->MinTime(1.0); \
  BENCHMARK_CAPTURE(side_by_side, name, std::string(task), std::string(robot))->MinTime(2.0)
SCENE_BENCHMARKS(panda_shelf_2, "shelf_2", "panda");
SCENE_BENCHMARKS(ur5_shelf_2, "shelf_2", "ur5");
SCENE_BENCHMARKS(kmr_iiwa_shelf_2, "shelf_2", "kmr_iiwa");
SCENE_BENCHMARKS(kmr_iiwa_waiter_0, "waiter_0", "kmr_iiwa");
SCENE_BENCHMARKS(panda_tunnel_0, "tunnel_0", "panda");
BENCHMARK_CAPTURE(first_pass, panda_shelf_2_fast_path, std::string("shelf_2"), std::string("panda"), true)
    ->Iterations(5)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(first_pass, panda_shelf_2_fcl_alone, std::string("shelf_2"), std::string("panda"), false)
    ->Iterations(5)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(first_pass, ur5_shelf_2_fast_path, std::string("shelf_2"), std::string("ur5"), true)
    ->Iterations(5)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(first_pass, ur5_shelf_2_fcl_alone, std::string("shelf_2"), std::string("ur5"), false)
    ->Iterations(5)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(fit_spheres, ur5_shelf_2, std::string("shelf_2"), std::string("ur5"))->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(fit_fcl_bvhs, ur5_shelf_2, std::string("shelf_2"), std::string("ur5"))->Unit(benchmark::kMillisecond);
BENCHMARK(distance_query)->Unit(benchmark::kMicrosecond);
BENCHMARK(build_checker)->Unit(benchmark::kMillisecond);

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  RatioReporter reporter;
  benchmark::RunSpecifiedBenchmarks(&reporter);
  reporter.print_ratios();
  benchmark::Shutdown();
  return 0;
}
