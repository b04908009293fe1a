#pragma once
// The drawable meshes of a scene's parts, each in the part's own frame: what the synthetic video
// draws and what the model-based tracker matches against the image.
#include <string>
#include <vector>

#include "core/model/robot_model.h"
#include "perception/markers/marker_scene.h"
#include "perception/render/render_mesh.h"

namespace demoplan::perception {

// Every visual of the model's root link merged into one mesh in the link's frame (the first
// visual keeps its texture). Throws InputError naming `name` when it has no visual geometry.
RenderMesh part_render_mesh(const RobotModel& model, const std::string& name);

// A visual geometry as a mesh in its own frame; empty for a shape it cannot draw.
RenderMesh geometry_render_mesh(const Geometry& geometry);

// The meshes of the objects a marker scene lists, in its order, from the benchmark task or the
// cell it names (`scene_file` resolves the cell's relative path). Throws InputError naming the
// scene file and the object that has no model.
std::vector<RenderMesh> marker_scene_part_meshes(const MarkerScene& scene, const std::string& scene_file,
                                                 const std::string& data_dir);

}  // namespace demoplan::perception
