#include "core/placement/furniture_footprints.h"

#include <algorithm>
#include <cmath>

#include "core/demo/benchmark_scene.h"
#include "core/geometry/polygon_2d.h"
#include "core/placement/base_clearance.h"

namespace demoplan {

namespace {

// Points whose hull is the geometry's, in its own frame (a cylinder's circles as 16-gons).
std::vector<Eigen::Vector3d> hull_points(const Geometry& g) {
  std::vector<Eigen::Vector3d> out;
  if (const auto* box = std::get_if<BoxShape>(&g.shape)) {
    for (int c = 0; c < 8; ++c)
      out.push_back(0.5 * box->size.cwiseProduct(Eigen::Vector3d(c & 1 ? 1 : -1, c & 2 ? 1 : -1, c & 4 ? 1 : -1)));
  } else if (const auto* cyl = std::get_if<CylinderShape>(&g.shape)) {
    for (int k = 0; k < 16; ++k)
      for (double z : {-cyl->length / 2, cyl->length / 2})
        out.emplace_back(cyl->radius * std::cos(k * M_PI / 8), cyl->radius * std::sin(k * M_PI / 8), z);
  } else if (const auto* sphere = std::get_if<SphereShape>(&g.shape)) {
    for (int k = 0; k < 16; ++k) out.emplace_back(sphere->radius * std::cos(k * M_PI / 8), sphere->radius * std::sin(k * M_PI / 8), 0);
  } else if (const auto* mesh = std::get_if<MeshShape>(&g.shape); mesh && mesh->mesh) {
    for (const Eigen::Vector3f& v : mesh->mesh->vertices) out.push_back(v.cast<double>().cwiseProduct(mesh->scale));
  }
  return out;
}

}  // namespace

std::vector<Footprint> furniture_footprints(const Scene& scene) {
  std::vector<Footprint> out;
  const int pedestal = robot_pedestal(scene);
  for (size_t i = 0; i < scene.furniture.size(); ++i) {
    const SceneFurniture& f = scene.furniture[i];
    if (f.kind == kSupportBoxKind || static_cast<int>(i) == pedestal) continue;
    std::vector<Eigen::Vector2d> points;
    for (size_t l = 0; l < f.model.links.size(); ++l) {
      if (std::find(f.robot_ignored_links.begin(), f.robot_ignored_links.end(), f.model.links[l].name) !=
          f.robot_ignored_links.end())
        continue;
      for (const Geometry& g : f.model.links[l].collisions)
        for (const Eigen::Vector3d& p : hull_points(g)) points.push_back((f.link_poses[l] * g.origin * p).head<2>());
    }
    if (points.size() < 3) continue;
    Footprint fp{f.name, {}};
    for (int i : hull_2d(points)) fp.outline.push_back(points[static_cast<size_t>(i)]);
    out.push_back(std::move(fp));
  }
  return out;
}

}  // namespace demoplan
