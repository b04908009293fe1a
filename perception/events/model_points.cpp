#include "perception/events/model_points.h"

#include <algorithm>
#include <filesystem>
#include <variant>

#include "core/demo/benchmark_task.h"
#include "core/model/robot_model.h"

namespace demoplan::perception {

std::map<std::string, std::vector<Eigen::Vector3d>> benchmark_model_points(const std::string& data_dir,
                                                                            const std::string& task_name,
                                                                            size_t max_points) {
  std::map<std::string, std::vector<Eigen::Vector3d>> models;
  if (!std::filesystem::exists(std::filesystem::path(data_dir) / "tasks" / (task_name + ".json"))) return models;
  const BenchmarkTask task = load_benchmark_task(data_dir, task_name);
  for (const auto& obj : task.objects) {
    const RobotModel model = load_urdf(obj.urdf);
    auto& points = models[obj.id];
    for (const auto& g : model.links.front().collisions)
      if (const auto* m = std::get_if<MeshShape>(&g.shape); m && m->mesh) {
        const size_t step = std::max<size_t>(1, m->mesh->vertices.size() / std::max<size_t>(1, max_points));
        for (size_t i = 0; i < m->mesh->vertices.size(); i += step)
          points.push_back(g.origin * m->mesh->vertices[i].cast<double>().cwiseProduct(m->scale));
      }
  }
  return models;
}

}  // namespace demoplan::perception
