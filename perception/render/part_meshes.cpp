#include "perception/render/part_meshes.h"

#include <algorithm>
#include <filesystem>
#include <variant>

#include "core/cell/cell.h"
#include "core/cell/cell_scene.h"
#include "core/demo/benchmark_scene.h"
#include "core/demo/benchmark_task.h"
#include "core/error.h"
#include "core/model/kinematics.h"

namespace demoplan::perception {

namespace {
cv::Vec3f bgr_of(const Eigen::Vector4d& rgba) { return {float(rgba[2] * 255), float(rgba[1] * 255), float(rgba[0] * 255)}; }
}  // namespace

RenderMesh geometry_render_mesh(const Geometry& g, TextureUse texture) {
  if (const auto* b = std::get_if<BoxShape>(&g.shape)) return box_mesh(b->size, bgr_of(g.color));
  if (const auto* c = std::get_if<CylinderShape>(&g.shape)) return cylinder_mesh(c->radius, c->length, bgr_of(g.color));
  if (const auto* m = std::get_if<MeshShape>(&g.shape); m && m->mesh) return render_mesh(*m->mesh, m->scale, Pose::Identity(), texture);
  return {};
}

RenderMesh part_render_mesh(const RobotModel& model, const std::string& name, TextureUse texture) {
  RenderMesh part;
  if (!model.links.empty())
    for (const auto& g : model.links.front().visuals) {
      RenderMesh m = geometry_render_mesh(g, texture);
      if (m.triangles.empty()) continue;
      if (part.triangles.empty()) {
        part = std::move(m);
        if (!g.origin.isApprox(Pose::Identity()))
          for (auto& v : part.vertices) v = g.origin.cast<float>() * v;
      } else {
        part.append(m, g.origin);
      }
    }
  if (part.triangles.empty()) throw InputError(name, "visual", "the part has no visual geometry to draw");
  return part;
}

namespace {

void add_visuals(const RobotModel& model, const PoseVector& link_poses, const std::string& kind,
                 std::vector<FurnitureMesh>& out) {
  for (size_t l = 0; l < model.links.size(); ++l)
    for (const auto& g : model.links[l].visuals) {
      if (g.color[3] < 0.5) continue;  // see-through
      RenderMesh m = geometry_render_mesh(g);
      if (m.triangles.empty()) continue;
      FurnitureMesh f{std::move(m), link_poses[l] * g.origin, link_poses[l], kind, std::nullopt};
      if (const auto* b = std::get_if<BoxShape>(&g.shape)) f.box = b->size;
      out.push_back(std::move(f));
    }
}

Scene cell_scene_with_visuals(const MarkerScene& scene, const std::string& scene_file, const std::string& data_dir,
                              MeshCache& cache, std::string& cell_file) {
  cell_file = (std::filesystem::path(scene_file).parent_path() / scene.cell).string();
  CellSceneOptions options;
  options.data_dir = data_dir;
  options.load_visual_meshes = true;
  options.mesh_cache = &cache;
  return build_cell_scene(load_cell(cell_file), options);
}

// A part the scene gives as a box (a tray): its colour is RGB, a mesh's BGR.
RenderMesh box_part_mesh(const MarkedObject& o) {
  return box_mesh(*o.box, cv::Vec3f(o.box_rgb.z(), o.box_rgb.y(), o.box_rgb.x()));
}

}  // namespace

std::vector<FurnitureMesh> furniture_meshes(const BenchmarkTask& task) {
  std::vector<FurnitureMesh> out;
  for (const auto& f : task.furniture) {
    const RobotModel model = load_urdf(f.urdf);
    PoseVector links;
    forward_kinematics(model, Eigen::VectorXd::Zero(model.nq), Pose::Identity(), links);
    add_visuals(model, links, f.kind, out);
  }
  return out;
}

std::vector<FurnitureMesh> furniture_meshes(const Scene& scene) {
  std::vector<FurnitureMesh> out;
  for (const auto& f : scene.furniture) add_visuals(f.model, f.link_poses, "", out);
  return out;
}

std::vector<FurnitureMesh> marker_scene_furniture_meshes(const MarkerScene& scene, const std::string& scene_file,
                                                         const std::string& data_dir) {
  if (!scene.cell.empty()) {
    MeshCache cache;
    std::string cell_file;
    return furniture_meshes(cell_scene_with_visuals(scene, scene_file, data_dir, cache, cell_file));
  }
  if (scene.task.empty()) return {};
  return furniture_meshes(load_benchmark_task(data_dir, scene.task));
}

std::shared_ptr<const Scene> marker_scene_world(const MarkerScene& scene, const std::string& scene_file,
                                                const std::string& data_dir) {
  if (!scene.cell.empty()) {
    const std::string cell_file = (std::filesystem::path(scene_file).parent_path() / scene.cell).string();
    return std::make_shared<const Scene>(build_cell_scene(load_cell(cell_file), {.data_dir = data_dir}));
  }
  if (scene.task.empty()) return nullptr;
  const BenchmarkTask task = load_benchmark_task(data_dir, scene.task);
  std::string robot = scene.robot;
  if (robot.empty() && !task.robot_pose_files.empty()) robot = task.robot_pose_files.begin()->first;
  return std::make_shared<const Scene>(build_benchmark_scene(task, robot, scene.robot_pose));
}

std::vector<RenderMesh> marker_scene_part_meshes(const MarkerScene& scene, const std::string& scene_file,
                                                 const std::string& data_dir) {
  MeshCache cache;
  std::vector<RenderMesh> meshes;
  if (!scene.cell.empty()) {
    std::string cell_file;
    const Scene cell_scene = cell_scene_with_visuals(scene, scene_file, data_dir, cache, cell_file);
    for (const auto& o : scene.objects) {
      if (o.box) {
        meshes.push_back(box_part_mesh(o));
        continue;
      }
      const auto it = std::find_if(cell_scene.objects.begin(), cell_scene.objects.end(), [&](auto& s) { return s.id == o.id; });
      if (it == cell_scene.objects.end())
        throw InputError(scene_file, "objects", "object '" + o.id + "' is not a part of the cell " + cell_file);
      meshes.push_back(part_render_mesh(it->model, o.id));
    }
    return meshes;
  }
  if (scene.task.empty()) throw InputError(scene_file, "task", "the scene names neither a task nor a cell: no part models");
  const BenchmarkTask task = load_benchmark_task(data_dir, scene.task);
  UrdfOptions options;
  options.load_visual_meshes = true;
  options.mesh_cache = &cache;
  for (const auto& o : scene.objects) {
    if (o.box) {
      meshes.push_back(box_part_mesh(o));
      continue;
    }
    const auto it = std::find_if(task.objects.begin(), task.objects.end(), [&](auto& t) { return t.id == o.id; });
    if (it == task.objects.end())
      throw InputError(scene_file, "objects", "object '" + o.id + "' is not an object of task " + scene.task);
    meshes.push_back(part_render_mesh(load_urdf(it->urdf, options), o.id));
  }
  return meshes;
}

}  // namespace demoplan::perception
