#pragma once
// The six faces of an axis-aligned box as polygons in the box's frame, each counter-clockwise
// seen from outside: what a box-shaped part (a tray) can rest on or carry others on.
#include <vector>

#include <Eigen/Geometry>

namespace demoplan {

std::vector<std::vector<Eigen::Vector3d>> box_faces(const Eigen::AlignedBox3d& box);

}  // namespace demoplan
