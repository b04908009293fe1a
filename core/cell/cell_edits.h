#pragma once
// The edits the cell editor makes, Qt-free so tests and the CLI can make them too: a starter
// cell, names that do not clash, a part from a mesh file put down on a free spot of a support,
// and the demonstration kept in step with the parts.
#include <string>

#include "core/cell/cell.h"
#include "core/cell/cell_scene.h"
#include "core/demo/demonstration.h"

namespace demoplan {

// `base` when no robot, furniture or part of `cell` is named so, else "base 2", "base 3", ...
std::string unique_cell_name(const Cell& cell, const std::string& base);

// A new cell to be written to `file`: the bundled `robot` at the origin on a 0.75 m pedestal
// (a mobile robot on the floor) and a 1.2 x 0.8 x 0.75 m table in front of it, supports found on
// its top; no part yet.
Cell starter_cell(const std::string& file, const std::string& robot, const std::string& data_dir);

// `cell` with its robot replaced: the bundled robot `bundled` (a name of robots.json), or, when
// it is empty, the robot of `urdf` and `srdf` from disk (its package:// meshes looked for around
// the URDF, guess_package_paths, and those folders added to the cell's package_paths). The base
// pose is kept (a mobile robot's put on the floor); the start configuration becomes the new
// robot's own. Throws InputError naming the robot or the file; loading the cell's scene then says
// whether the robot itself can be read.
void replace_robot(Cell& cell, const std::string& bundled, const std::string& urdf, const std::string& srdf,
                   const std::string& data_dir);

// Makes the cell's robot from disk mobile (its base moved on the floor through its own x, y, yaw
// joints) or fixed. `scene` is the cell's scene as it is (its robot model and furniture). Made
// mobile, the robot goes onto the floor and the pedestal it stood on (robot_pedestal) is taken
// out; made fixed, a robot standing on nothing gets a 0.75 m pedestal as a new cell's has.
// Throws InputError for a bundled robot (its data says whether it is mobile) and for a URDF
// without the planar base joints a mobile base needs (mobile_base_problem).
void set_robot_mobile(Cell& cell, const Scene& scene, bool mobile);

// Metres per unit of a mesh file, guessed from its size: CAD files of shop-floor parts are in
// millimetres (an extent above 3 units), scanned ones in metres.
double guess_unit_scale(const std::string& mesh_file);

// Adds a part made from `mesh_file` (metres per unit `scale`), named after the file, resting on
// a free spot of a support where the robot and the other parts leave room (the same draw for
// the same cell). Returns its index. Throws InputError naming the file when the mesh cannot be
// read, the part cannot rest or be grasped, or no support has room for it.
int add_part_from_mesh(Cell& cell, const std::string& mesh_file, double scale, const CellSceneOptions& options = {});

// The demonstration for `scene`'s parts after parts were added or removed: a part kept keeps
// its events and poses, a new part rests where `start` puts it at every event. Throws
// InputError naming the part when a removed part has events (delete them first).
Demonstration demonstration_for_parts(const Demonstration& demo, const Scene& scene, const SceneState& start);

}  // namespace demoplan
