#pragma once
// Rigid transforms: conversions between the conventions of URDF, SRDF and the benchmark files.
#include <Eigen/Geometry>

namespace demoplan {

using Pose = Eigen::Isometry3d;
using Vector6d = Eigen::Matrix<double, 6, 1>;

// URDF rpy: R = Rz(yaw) * Ry(pitch) * Rx(roll).
Eigen::Matrix3d rotation_from_rpy(double roll, double pitch, double yaw);
Pose pose_from_xyz_rpy(const Eigen::Vector3d& xyz, const Eigen::Vector3d& rpy);
// The inverse: (roll, pitch, yaw) with pitch in [-pi/2, pi/2]; at pitch = +-pi/2 roll is 0.
Eigen::Vector3d rpy_from_rotation(const Eigen::Matrix3d& R);

// Translation plus a quaternion; the quaternion is normalised.
Pose pose_from_xyz_quat(const Eigen::Vector3d& xyz, const Eigen::Quaterniond& q);

// SE(3) logarithm as (linear, angular), the 6-vector pinocchio's log6 returns.
Vector6d log6(const Pose& T);
// SO(3) logarithm as a rotation vector.
Eigen::Vector3d log3(const Eigen::Matrix3d& R);

// Between two poses: translation linear, rotation spherical (slerp); s = 0 gives a, 1 gives b.
Pose interpolate(const Pose& a, const Pose& b, double s);

// True when R is a rotation: R^T R = I and det R = 1, both within tol.
bool is_rotation(const Eigen::Matrix3d& R, double tol = 1e-6);

// The axis of a body (its frame: +-x, +-y or +-z) that `world_R` turns nearest the world's +z:
// the face of a box that looks up (the first axis of equally near ones).
Eigen::Vector3d axis_nearest_up(const Eigen::Matrix3d& world_R);

}  // namespace demoplan
