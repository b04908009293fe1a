#include "perception/tracking/carrier_top.h"

#include <cmath>

#include "core/geometry/box_faces.h"

namespace demoplan::perception {

std::optional<std::vector<Eigen::Vector3d>> carrier_top(const Eigen::AlignedBox3d& box, const Pose& world_T_part,
                                                        double max_tilt) {
  // The face whose outward normal looks most nearly up in the world.
  std::optional<std::vector<Eigen::Vector3d>> top;
  double up = std::cos(max_tilt);
  for (const auto& face : box_faces(box)) {
    const Eigen::Vector3d normal = (world_T_part.linear() * (face[1] - face[0]).cross(face[2] - face[1])).normalized();
    if (normal.z() < up) continue;
    up = normal.z();
    top.emplace();
    for (const auto& corner : face) top->push_back(world_T_part * corner);
  }
  return top;
}

}  // namespace demoplan::perception
