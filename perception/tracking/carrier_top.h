#pragma once
// The top of a part that carries others (a tray, a board the demonstrator moves with parts on
// it): what those parts rest on, and so what holds their depth, which their images alone give
// centimetres off a few metres away.
#include <optional>
#include <vector>

#include <Eigen/Geometry>

#include "core/geometry/se3.h"

namespace demoplan::perception {

// The face of the part's box (part frame) that looks up in the world at `world_T_part`, as a
// polygon in the world, counter-clockwise seen from above; none when no face is within
// `max_tilt` (rad) of level.
std::optional<std::vector<Eigen::Vector3d>> carrier_top(const Eigen::AlignedBox3d& box, const Pose& world_T_part,
                                                        double max_tilt = 10.0 * M_PI / 180);

}  // namespace demoplan::perception
