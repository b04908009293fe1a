#pragma once
// Markers stuck on a part where the operator clicks in the 3D view (the cell editor): a square
// centred at the clicked point, flat on the face, printed side out, with the cell's next free id.
#include <Eigen/Core>

#include "core/cell/cell.h"
#include "core/model/mesh.h"

namespace demoplan {

// A marker's axes on a face with outward `normal` (part frame): z along the normal, the image's
// top edge (+y) along the part's +z, or its +x on a face that looks up or down; x = y cross z.
// (synth's box-face markers follow the same rule.)
Eigen::Matrix3d marker_frame_on_face(const Eigen::Vector3d& normal);

// The smallest marker id no part of the cell uses.
int free_marker_id(const Cell& cell);

// A marker of black side `size` (m) centred at `point` on the face whose outward normal is
// `normal` (both in the part frame, the mesh scaled by `scale` metres per unit), axes
// marker_frame_on_face(normal), 1 mm in front of the face (as synth's box-face markers), id
// free_marker_id(cell).
// Throws InputError naming the part when the square does not lie on the face: a corner farther
// than `flatness` (m) from the mesh's surface along the normal (an edge, a hole, a curve).
CellMarker marker_on_face(const Cell& cell, int part, const TriangleMesh& mesh, const Eigen::Vector3d& point,
                          const Eigen::Vector3d& normal, double size, double flatness = 0.003);

}  // namespace demoplan
