// SE(3) helpers: the URDF rpy convention and the logarithm used by the benchmark's grasp test.
#include <gtest/gtest.h>

#include <cmath>

#include "core/geometry/se3.h"

using namespace demoplan;

TEST(Se3, RpyIsZyxIntrinsic) {
  // URDF: R = Rz(yaw) Ry(pitch) Rx(roll). Rotating x by yaw=90deg about z gives y.
  const Eigen::Matrix3d R = rotation_from_rpy(0, 0, M_PI / 2);
  EXPECT_TRUE(R.col(0).isApprox(Eigen::Vector3d::UnitY(), 1e-12));
  // roll then pitch: Ry(90) Rx(90) maps z to ... Ry(90)(-y) = -y.
  const Eigen::Matrix3d R2 = rotation_from_rpy(M_PI / 2, M_PI / 2, 0);
  EXPECT_TRUE((R2 * Eigen::Vector3d::UnitZ()).isApprox(-Eigen::Vector3d::UnitY(), 1e-12));
  EXPECT_TRUE((R2 * Eigen::Vector3d::UnitX()).isApprox(-Eigen::Vector3d::UnitZ(), 1e-12));
}

TEST(Se3, Log6OfPureTranslationIsTheTranslation) {
  Pose T = Pose::Identity();
  T.translation() << 0.1, -0.2, 0.3;
  const Vector6d v = log6(T);
  EXPECT_NEAR((v.head<3>() - Eigen::Vector3d(0.1, -0.2, 0.3)).norm(), 0.0, 1e-15);
  EXPECT_NEAR(v.tail<3>().norm(), 0.0, 1e-15);
}

TEST(Se3, Log6InvertsTheExponentialOfAScrewMotion) {
  // exp of twist (v, w): a rotation of angle |w| about axis w/|w| through point p with pitch.
  const Eigen::Vector3d w(0.3, -0.5, 0.7), v(0.2, 0.1, -0.4);
  Eigen::Matrix<double, 4, 4> X = Eigen::Matrix4d::Zero();
  X.topLeftCorner<3, 3>() << 0, -w.z(), w.y(), w.z(), 0, -w.x(), -w.y(), w.x(), 0;
  X.topRightCorner<3, 1>() = v;
  // Matrix exponential by series (converges fast for |w| ~ 1).
  Eigen::Matrix4d E = Eigen::Matrix4d::Identity(), term = Eigen::Matrix4d::Identity();
  for (int k = 1; k < 30; ++k) {
    term = term * X / k;
    E += term;
  }
  Pose T;
  T.matrix() = E;
  const Vector6d out = log6(T);
  EXPECT_NEAR((out.head<3>() - v).norm(), 0.0, 1e-12);
  EXPECT_NEAR((out.tail<3>() - w).norm(), 0.0, 1e-12);
}

TEST(Se3, IsRotationRejectsScaledAndReflectedMatrices) {
  EXPECT_TRUE(is_rotation(rotation_from_rpy(0.1, 0.2, 0.3)));
  EXPECT_FALSE(is_rotation(1.01 * Eigen::Matrix3d::Identity()));
  EXPECT_FALSE(is_rotation(Eigen::Vector3d(1, 1, -1).asDiagonal().toDenseMatrix()));
  Eigen::Matrix3d nan = Eigen::Matrix3d::Identity();
  nan(0, 1) = std::nan("");
  EXPECT_FALSE(is_rotation(nan));
}

TEST(Se3, InterpolateIsLinearInTranslationAndSphericalInRotation) {
  const Pose a = pose_from_xyz_rpy({0.1, -0.2, 0.3}, {0.0, 0.0, 0.2});
  const Pose b = pose_from_xyz_rpy({0.5, 0.2, 0.1}, {0.0, 0.0, 1.4});
  EXPECT_TRUE(interpolate(a, b, 0.0).isApprox(a, 1e-12));
  EXPECT_TRUE(interpolate(a, b, 1.0).isApprox(b, 1e-12));
  const Pose quarter = interpolate(a, b, 0.25);
  EXPECT_TRUE(quarter.translation().isApprox(Eigen::Vector3d(0.2, -0.1, 0.25), 1e-12));
  // About one axis (z), slerp turns by the same fraction of the angle: 0.2 + 0.25 * 1.2.
  EXPECT_TRUE(quarter.linear().isApprox(rotation_from_rpy(0, 0, 0.5), 1e-12));
  EXPECT_TRUE(is_rotation(interpolate(a, b, 0.7).linear()));
}

TEST(Se3, AxisNearestUpIsTheBodyAxisTurnedNearestTheWorldsVertical) {
  EXPECT_TRUE(axis_nearest_up(Eigen::Matrix3d::Identity()).isApprox(Eigen::Vector3d::UnitZ()));
  // Upside down and tilted 20 degrees: its -z looks up.
  EXPECT_TRUE(axis_nearest_up(rotation_from_rpy(M_PI - 0.35, 0, 0.7)).isApprox(-Eigen::Vector3d::UnitZ()));
  // Laid on its side (turned 80 degrees about x): its +y looks up (y turns towards +z).
  EXPECT_TRUE(axis_nearest_up(rotation_from_rpy(1.4, 0, 0)).isApprox(Eigen::Vector3d::UnitY()));
  // Turned 100 degrees about y: its x turns towards -z, so -x looks up.
  EXPECT_TRUE(axis_nearest_up(rotation_from_rpy(0, 1.75, 0)).isApprox(-Eigen::Vector3d::UnitX()));
}
