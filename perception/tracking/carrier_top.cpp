#include "perception/tracking/carrier_top.h"

#include <algorithm>
#include <cmath>

namespace demoplan::perception {

std::optional<std::vector<Eigen::Vector3d>> carrier_top(const Eigen::AlignedBox3d& box, const Pose& world_T_part,
                                                        double max_tilt) {
  // The box axis nearest the world's vertical, and which of its two faces is up.
  const Eigen::Vector3d nearest = axis_nearest_up(world_T_part.linear());
  int axis = 0;
  nearest.cwiseAbs().maxCoeff(&axis);
  const double sign = nearest[axis];
  if ((world_T_part.linear() * nearest).z() < std::cos(max_tilt)) return std::nullopt;
  const int u = (axis + 1) % 3, v = (axis + 2) % 3;
  std::vector<Eigen::Vector3d> top;
  for (const auto& [a, b] : {std::pair{0, 0}, std::pair{1, 0}, std::pair{1, 1}, std::pair{0, 1}}) {
    Eigen::Vector3d corner;
    corner[axis] = sign > 0 ? box.max()[axis] : box.min()[axis];
    corner[u] = a ? box.max()[u] : box.min()[u];
    corner[v] = b ? box.max()[v] : box.min()[v];
    top.push_back(world_T_part * corner);
  }
  const Eigen::Vector3d normal = (top[1] - top[0]).cross(top[2] - top[1]);
  if (normal.z() < 0) std::reverse(top.begin(), top.end());
  return top;
}

}  // namespace demoplan::perception
