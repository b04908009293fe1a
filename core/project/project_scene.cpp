#include "core/project/project_scene.h"

#include "core/cell/cell_scene.h"

namespace demoplan {

ReferencedScene load_referenced_scene(const SceneReference& ref, const std::string& data_dir,
                                      const SceneLoadOptions& options) {
  const std::string dir = ref.data_dir.empty() ? data_dir : ref.data_dir;
  ReferencedScene out;
  if (ref.is_cell()) {
    const Cell cell = load_cell(ref.cell);
    out.scene = std::make_shared<const Scene>(build_cell_scene(
        cell, {.data_dir = dir, .load_visual_meshes = options.load_visual_meshes, .mesh_cache = options.mesh_cache}));
    return out;
  }
  auto task = std::make_shared<const BenchmarkTask>(load_benchmark_task(dir, ref.task));
  Scene scene = build_benchmark_scene(*task, ref.robot, ref.pose, options);
  if (ref.base) move_benchmark_robot(scene, load_benchmark_robot(dir, ref.robot), ref.base->pose());
  out.scene = std::make_shared<const Scene>(std::move(scene));
  out.task = std::move(task);
  return out;
}

}  // namespace demoplan
