// Nearest-neighbour queries in a planning state as the trees grow: query time at 1k, 10k and
// 100k configurations (9-D, Panda-sized), against a linear scan.
#include <benchmark/benchmark.h>

#include <random>

#include "core/planning/nearest_neighbors.h"

using namespace demoplan;

namespace {

std::vector<Eigen::VectorXd> points(size_t n, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-3, 3);
  std::vector<Eigen::VectorXd> out(n, Eigen::VectorXd(9));
  for (auto& p : out)
    for (int i = 0; i < 9; ++i) p[i] = u(rng);
  return out;
}

void query(benchmark::State& st) {
  const size_t n = static_cast<size_t>(st.range(0));
  NearestNeighbors nn(9);
  const auto data = points(n, 1);
  for (size_t i = 0; i < n; ++i) nn.add(static_cast<int>(i), data[i]);
  const auto queries = points(1024, 2);
  size_t k = 0;
  for (auto _ : st) benchmark::DoNotOptimize(nn.nearest(queries[k++ % queries.size()]));
}

void linear_scan(benchmark::State& st) {
  const size_t n = static_cast<size_t>(st.range(0));
  const auto data = points(n, 1);
  const auto queries = points(1024, 2);
  size_t k = 0;
  for (auto _ : st) {
    const auto& q = queries[k++ % queries.size()];
    double best = 1e300;
    int id = -1;
    for (size_t i = 0; i < n; ++i)
      if (double d = (data[i] - q).squaredNorm(); d < best) best = d, id = static_cast<int>(i);
    benchmark::DoNotOptimize(id);
  }
}

void insert(benchmark::State& st) {
  const auto data = points(100000, 1);
  for (auto _ : st) {
    NearestNeighbors nn(9);
    for (size_t i = 0; i < data.size(); ++i) nn.add(static_cast<int>(i), data[i]);
    benchmark::DoNotOptimize(nn.size());
  }
  st.counters["inserts_per_s"] = benchmark::Counter(static_cast<double>(st.iterations() * 100000), benchmark::Counter::kIsRate);
}

}  // namespace

BENCHMARK(query)->Arg(1000)->Arg(10000)->Arg(100000)->Unit(benchmark::kMicrosecond);
BENCHMARK(linear_scan)->Arg(1000)->Arg(10000)->Arg(100000)->Unit(benchmark::kMicrosecond);
BENCHMARK(insert)->Unit(benchmark::kMillisecond);

BENCHMARK_MAIN();
