#include "core/geometry/planar_motion.h"

#include <cmath>

namespace demoplan {

Pose PlanarMotion::at(double s) const {
  Pose T = Pose::Identity();
  T.linear() = Eigen::AngleAxisd(s * yaw, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  T.translation() = centre + s * shift - T.linear() * centre;
  return T;
}

PlanarMotion fit_planar_motion(const std::vector<Eigen::Vector3d>& from, const std::vector<Eigen::Vector3d>& to) {
  PlanarMotion m;
  if (from.empty() || from.size() != to.size()) return m;
  Eigen::Vector3d cf = Eigen::Vector3d::Zero(), ct = Eigen::Vector3d::Zero();
  for (size_t i = 0; i < from.size(); ++i) cf += from[i], ct += to[i];
  cf /= static_cast<double>(from.size());
  ct /= static_cast<double>(to.size());
  double sxx = 0, sxy = 0;
  for (size_t i = 0; i < from.size(); ++i) {
    const Eigen::Vector2d p = (from[i] - cf).head<2>(), q = (to[i] - ct).head<2>();
    sxx += p.dot(q);
    sxy += p.x() * q.y() - p.y() * q.x();
  }
  m.centre = cf;
  m.shift = ct - cf;
  m.yaw = from.size() > 1 ? std::atan2(sxy, sxx) : 0.0;
  return m;
}

}  // namespace demoplan
