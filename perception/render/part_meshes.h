#pragma once
// The drawable meshes of a scene's parts, each in the part's own frame, and of its furniture, in
// the world: what the synthetic video draws and what the model-based tracker matches against the
// image (the furniture as what hides parts).
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/demo/benchmark_task.h"
#include "core/model/robot_model.h"
#include "core/scene/scene.h"
#include "perception/markers/marker_scene.h"
#include "perception/render/render_mesh.h"

namespace demoplan::perception {

// Every visual of the model's root link merged into one mesh in the link's frame (the first
// visual keeps its texture). Throws InputError naming `name` when it has no visual geometry.
RenderMesh part_render_mesh(const RobotModel& model, const std::string& name,
                            TextureUse texture = TextureUse::Load);

// A visual geometry as a mesh in its own frame; empty for a shape it cannot draw.
RenderMesh geometry_render_mesh(const Geometry& geometry, TextureUse texture = TextureUse::Load);

// The meshes of the objects a marker scene lists, in its order, from the benchmark task or the
// cell it names (`scene_file` resolves the cell's relative path). Throws InputError naming the
// scene file and the object that has no model.
std::vector<RenderMesh> marker_scene_part_meshes(const MarkerScene& scene, const std::string& scene_file,
                                                 const std::string& data_dir);

// The scene a marker scene shows, without visual meshes: the cell it names, or its benchmark
// task with its robot at its pose (a task's scene that names no robot: the task's first). Null
// when it names neither. Throws InputError for files that cannot be read.
std::shared_ptr<const Scene> marker_scene_world(const MarkerScene& scene, const std::string& scene_file,
                                                const std::string& data_dir);

// One visual of a piece of furniture, placed in the world.
struct FurnitureMesh {
  RenderMesh mesh;
  Pose world_T_mesh = Pose::Identity();
  Pose world_T_link = Pose::Identity();   // of the link the visual belongs to
  std::string kind;                       // the furniture's kind ("table", "shelf"; "" in a cell)
  std::optional<Eigen::Vector3d> box;     // the visual's size when it is a box
};

// Every drawn visual of the task's furniture (see-through ones, alpha < 0.5, left out: the
// tunnel's closing walls) or of a scene's (a cell's, built with its visual meshes).
std::vector<FurnitureMesh> furniture_meshes(const BenchmarkTask& task);
std::vector<FurnitureMesh> furniture_meshes(const Scene& scene);
// Those of the task or cell a marker scene names.
std::vector<FurnitureMesh> marker_scene_furniture_meshes(const MarkerScene& scene, const std::string& scene_file,
                                                         const std::string& data_dir);

}  // namespace demoplan::perception
