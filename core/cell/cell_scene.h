#pragma once
// The Scene of a cell (cell.h), built as a benchmark scene is: downstream of the scene nothing
// knows which it came from. Parts get their contact polygons from their resting placements and
// their handles from the generator for the robot's gripper where the cell says "auto"; furniture
// gets its supports from its upward faces.
#include <string>
#include <vector>

#include "core/cell/cell.h"
#include "core/part/grasp_handles.h"
#include "core/scene/scene.h"

namespace demoplan {

struct CellSceneOptions {
  std::string data_dir;  // the bundled benchmark data (robots.json); empty: the caller's default
  bool load_visual_meshes = false;
  MeshCache* mesh_cache = nullptr;
};

// What was computed for the user's files, to show and to explain.
struct CellPartReport {
  std::string part;
  int placements = 0;       // resting placements (contact polygons) found
  GraspReport grasps;       // when the handles were generated
  bool generated = false;   // handles generated (else the cell's own)
  bool open_mesh = false;   // the mesh does not close: its volume is unknown, placements from the hull still hold
};
struct CellSceneReport {
  std::vector<CellPartReport> parts;
  std::vector<int> supports;  // support polygons per furniture
};

// Throws InputError naming the cell file (or the file it names) and the field: a missing mesh,
// URDF or SRDF, a gripper naming an unknown link, a part without a handle (saying why), a part
// with no resting placement.
Scene build_cell_scene(const Cell& cell, const CellSceneOptions& options = {}, CellSceneReport* report = nullptr);

// The robot at its initial configuration, the parts where the cell puts them.
SceneState cell_start_state(const Cell& cell, const Scene& scene);

}  // namespace demoplan
