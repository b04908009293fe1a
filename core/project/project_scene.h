#pragma once
// The scene a project refers to (SceneReference), a benchmark task's or a cell's, as the GUI and
// the CLI load it. Downstream of the scene nothing knows which.
#include <memory>
#include <string>

#include "core/demo/benchmark_scene.h"
#include "core/project/project.h"

namespace demoplan {

struct ReferencedScene {
  std::shared_ptr<const Scene> scene;
  std::shared_ptr<const BenchmarkTask> task;  // null for a cell
};

// `data_dir`: the benchmark data when the reference names none. Throws InputError.
ReferencedScene load_referenced_scene(const SceneReference& ref, const std::string& data_dir,
                                      const SceneLoadOptions& options = {});

}  // namespace demoplan
