#pragma once
// The faces of an axis-aligned box as polygons in the box's frame, each counter-clockwise seen
// from outside: what a box-shaped part (a tray) can rest on or carry others on. Six, or two for
// a flat box (a tray given without thickness): a face without area has no side to stand on.
#include <vector>

#include <Eigen/Geometry>

namespace demoplan {

std::vector<std::vector<Eigen::Vector3d>> box_faces(const Eigen::AlignedBox3d& box);

}  // namespace demoplan
