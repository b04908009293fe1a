#pragma once
// A camera's pose from where it is and what it looks at, in OpenCV's camera axes (z forward, y
// down in the image): its x axis level (across the world's up), or along the world's x when it
// looks straight up or down.
#include <cmath>

#include "core/geometry/se3.h"

namespace demoplan::perception {

inline Pose look_at(const Eigen::Vector3d& eye, const Eigen::Vector3d& target) {
  const Eigen::Vector3d z = (target - eye).normalized();
  const Eigen::Vector3d across = z.cross(Eigen::Vector3d::UnitZ());
  const Eigen::Vector3d x = across.norm() > 1e-6 ? across.normalized() : Eigen::Vector3d::UnitX();
  Pose T = Pose::Identity();
  T.linear().col(0) = x;
  T.linear().col(1) = z.cross(x);
  T.linear().col(2) = z;
  T.translation() = eye;
  return T;
}

}  // namespace demoplan::perception
