#include "core/geometry/se3.h"

#include <cmath>

namespace demoplan {

Eigen::Matrix3d rotation_from_rpy(double roll, double pitch, double yaw) {
  return (Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()) *
          Eigen::AngleAxisd(pitch, Eigen::Vector3d::UnitY()) *
          Eigen::AngleAxisd(roll, Eigen::Vector3d::UnitX()))
      .toRotationMatrix();
}

Eigen::Vector3d rpy_from_rotation(const Eigen::Matrix3d& R) {
  const double c = std::hypot(R(0, 0), R(1, 0));  // |cos(pitch)|; atan2 keeps pitch exact near +-pi/2
  const double pitch = std::atan2(-R(2, 0), c);
  if (c < 1e-10)  // gimbal lock: only roll - yaw (or roll + yaw) is defined
    return {0.0, pitch, std::atan2(-R(0, 1), R(1, 1))};
  return {std::atan2(R(2, 1), R(2, 2)), pitch, std::atan2(R(1, 0), R(0, 0))};
}

Pose pose_from_xyz_rpy(const Eigen::Vector3d& xyz, const Eigen::Vector3d& rpy) {
  Pose T = Pose::Identity();
  T.linear() = rotation_from_rpy(rpy.x(), rpy.y(), rpy.z());
  T.translation() = xyz;
  return T;
}

Pose pose_from_xyz_quat(const Eigen::Vector3d& xyz, const Eigen::Quaterniond& q) {
  Pose T = Pose::Identity();
  T.linear() = q.normalized().toRotationMatrix();
  T.translation() = xyz;
  return T;
}

Pose interpolate(const Pose& a, const Pose& b, double s) {
  Pose out = Pose::Identity();
  out.translation() = (1 - s) * a.translation() + s * b.translation();
  out.linear() = Eigen::Quaterniond(a.linear()).slerp(s, Eigen::Quaterniond(b.linear())).toRotationMatrix();
  return out;
}

Eigen::Vector3d log3(const Eigen::Matrix3d& R) {
  const Eigen::AngleAxisd aa(R);
  return aa.angle() * aa.axis();
}

Vector6d log6(const Pose& T) {
  // log of (R, p): omega = log3(R), v = V^-1(omega) p.
  const Eigen::Vector3d w = log3(T.linear());
  const double theta = w.norm();
  const Eigen::Vector3d& p = T.translation();
  Eigen::Vector3d v;
  if (theta < 1e-9) {
    v = p - 0.5 * w.cross(p);
  } else {
    Eigen::Matrix3d W;
    W << 0, -w.z(), w.y(), w.z(), 0, -w.x(), -w.y(), w.x(), 0;
    const double half = 0.5 * theta;
    const double coef = (1.0 - half * std::cos(half) / std::sin(half)) / (theta * theta);
    const Eigen::Matrix3d V_inv = Eigen::Matrix3d::Identity() - 0.5 * W + coef * W * W;
    v = V_inv * p;
  }
  Vector6d out;
  out << v, w;
  return out;
}

bool is_rotation(const Eigen::Matrix3d& R, double tol) {
  if (!R.allFinite()) return false;
  return (R.transpose() * R - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff() <= tol &&
         std::abs(R.determinant() - 1.0) <= tol;
}

Eigen::Vector3d axis_nearest_up(const Eigen::Matrix3d& world_R) {
  const Eigen::Vector3d up = world_R.row(2).transpose();  // the world's +z in the body frame
  int axis = 0;
  up.cwiseAbs().maxCoeff(&axis);
  return std::copysign(1.0, up[axis]) * Eigen::Vector3d::Unit(axis);
}

}  // namespace demoplan
