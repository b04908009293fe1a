#include "core/geometry/box_overlap.h"

#include <cmath>

namespace demoplan {

bool boxes_overlap(const Pose& a, const Eigen::Vector3d& half_a, const Pose& b, const Eigen::Vector3d& half_b) {
  // b's axes and centre in a's frame (Gottschalk's OBB test).
  const Eigen::Matrix3d R = a.linear().transpose() * b.linear();
  const Eigen::Vector3d t = a.linear().transpose() * (b.translation() - a.translation());
  // A small epsilon keeps near-parallel edge axes (cross products close to zero) from
  // declaring a separation that rounding made up.
  const Eigen::Matrix3d AbsR = R.cwiseAbs().array() + 1e-9;
  for (int i = 0; i < 3; ++i)
    if (std::abs(t[i]) > half_a[i] + half_b.dot(AbsR.row(i).transpose())) return false;
  for (int j = 0; j < 3; ++j)
    if (std::abs(t.dot(R.col(j))) > half_a.dot(AbsR.col(j)) + half_b[j]) return false;
  for (int i = 0; i < 3; ++i) {
    const int i1 = (i + 1) % 3, i2 = (i + 2) % 3;
    for (int j = 0; j < 3; ++j) {
      const int j1 = (j + 1) % 3, j2 = (j + 2) % 3;
      const double ra = half_a[i1] * AbsR(i2, j) + half_a[i2] * AbsR(i1, j);
      const double rb = half_b[j1] * AbsR(i, j2) + half_b[j2] * AbsR(i, j1);
      if (std::abs(t[i2] * R(i1, j) - t[i1] * R(i2, j)) > ra + rb) return false;
    }
  }
  return true;
}

}  // namespace demoplan
