#pragma once
// The Scene of a cell (cell.h), built as a benchmark scene is: downstream of the scene nothing
// knows which it came from. Parts get their contact polygons from their resting placements and
// their handles from the generator for the robot's gripper where the cell says "auto"; furniture
// gets its supports from its upward faces.
#include <functional>
#include <map>
#include <mutex>
#include <string>
#include <vector>

#include "core/cell/cell.h"
#include "core/part/grasp_handles.h"
#include "core/scene/scene.h"

namespace demoplan {

// What a part's mesh gives (resting placements, generated handles), kept between builds of the
// same cell: the cell editor rebuilds the scene on every change, and moving a part or a table
// changes neither. Keyed by everything they depend on (mesh, scale, gripper, grasp options).
// Thread-safe.
class CellPartCache {
public:
  struct Entry {
    std::vector<Polygon3> placements;
    GraspReport grasps;
  };
  // The entry for `key`, made by `make` the first time.
  Entry get(const std::string& key, const std::function<Entry()>& make);

private:
  std::mutex mutex_;
  std::map<std::string, Entry> entries_;
};

struct CellSceneOptions {
  std::string data_dir;  // the bundled benchmark data (robots.json); empty: the caller's default
  bool load_visual_meshes = false;
  MeshCache* mesh_cache = nullptr;
  CellPartCache* part_cache = nullptr;
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
