// What one change in the cell editor costs (issue 15): Document::editCell rebuilds the scene of
// the edited cell (its parts' resting placements and generated handles included, meshes shared
// through the document's cache) and writes the cell file; Add Part also finds the part a free
// spot on a support. Run on the bundled example cells.
//
//   build/bench/bench_cell_edit
#include <benchmark/benchmark.h>

#include <filesystem>

#include "core/cell/cell_edits.h"
#include "core/cell/cell_scene.h"

namespace {

using namespace demoplan;

const std::string kCells = std::string(DEMOPLAN_DATA_DIR) + "/../cells";

// `cached`: the parts' placements and handles kept between rebuilds, as the editor keeps them
// (a move changes neither); without, every rebuild derives them again (a first load).
void rebuild(benchmark::State& state, const char* name, bool cached) {
  const Cell cell = load_cell(kCells + "/" + name + ".json");
  MeshCache meshes;
  CellPartCache parts;
  const CellSceneOptions options{.data_dir = DEMOPLAN_DATA_DIR, .load_visual_meshes = true, .mesh_cache = &meshes,
                                 .part_cache = cached ? &parts : nullptr};
  for (auto _ : state) benchmark::DoNotOptimize(build_cell_scene(cell, options));
}
BENCHMARK_CAPTURE(rebuild, ur5_workbench, "ur5_workbench", false)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(rebuild, ur5_workbench_cached, "ur5_workbench", true)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(rebuild, iiwa_shelf, "iiwa_shelf", false)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(rebuild, iiwa_shelf_cached, "iiwa_shelf", true)->Unit(benchmark::kMillisecond);

void write(benchmark::State& state) {
  Cell cell = load_cell(kCells + "/ur5_workbench.json");
  const std::string file = (std::filesystem::temp_directory_path() / "demoplan_bench_cell_edit.json").string();
  for (auto _ : state) save_cell(file, cell);
  std::filesystem::remove(file);
}
BENCHMARK(write)->Unit(benchmark::kMillisecond);

void add_part(benchmark::State& state) {
  const Cell cell = load_cell(kCells + "/ur5_workbench.json");
  const std::string mesh = kCells + "/parts/bracket.stl";
  for (auto _ : state) {
    Cell c = cell;
    benchmark::DoNotOptimize(add_part_from_mesh(c, mesh, 0.001, {.data_dir = DEMOPLAN_DATA_DIR}));
  }
}
BENCHMARK(add_part)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
