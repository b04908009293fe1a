#include "core/geometry/box_faces.h"

namespace demoplan {

std::vector<std::vector<Eigen::Vector3d>> box_faces(const Eigen::AlignedBox3d& box) {
  std::vector<std::vector<Eigen::Vector3d>> faces;
  for (int axis = 0; axis < 3; ++axis)
    for (const bool high : {false, true}) {
      // (u, v, axis) is right-handed: corners in (u, v) order go counter-clockwise seen from
      // +axis, and are reversed for the face looking down -axis.
      const int u = (axis + 1) % 3, v = (axis + 2) % 3;
      if (!(box.sizes()[u] > 0 && box.sizes()[v] > 0)) continue;
      std::vector<Eigen::Vector3d> face;
      for (const auto& [a, b] : {std::pair{0, 0}, std::pair{1, 0}, std::pair{1, 1}, std::pair{0, 1}}) {
        Eigen::Vector3d corner;
        corner[axis] = high ? box.max()[axis] : box.min()[axis];
        corner[u] = a ? box.max()[u] : box.min()[u];
        corner[v] = b ? box.max()[v] : box.min()[v];
        face.push_back(corner);
      }
      if (!high) std::swap(face[1], face[3]);
      faces.push_back(std::move(face));
    }
  return faces;
}

}  // namespace demoplan
