// Forward kinematics of the bundled Panda and UR5 URDFs against the manufacturers' published
// Denavit-Hartenberg parameters. The DH chains below are computed here from the textbook
// formulas with plain Eigen, so they share no code with the URDF loader or the FK under test.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "core/model/kinematics.h"
#include "core/model/robot_model.h"

namespace {

using demoplan::Pose;
using demoplan::PoseVector;
using demoplan::RobotModel;
constexpr double kPi = std::numbers::pi;
constexpr double kPosTol = 1e-6;  // m
constexpr double kRotTol = 1e-6;  // rad

const std::string kData = DEMOPLAN_DATA_DIR;

Pose rot_x(double a) { return Pose(Eigen::AngleAxisd(a, Eigen::Vector3d::UnitX())); }
Pose rot_z(double a) { return Pose(Eigen::AngleAxisd(a, Eigen::Vector3d::UnitZ())); }
Pose trans_x(double d) { return Pose(Eigen::Translation3d(d, 0, 0)); }
Pose trans_z(double d) { return Pose(Eigen::Translation3d(0, 0, d)); }

// Rotation angle of R_expected^T R_actual (atan2 form: accurate near 0 and near pi) and the
// distance between the origins.
struct PoseError {
  double position;
  double angle;
};
PoseError pose_error(const Pose& expected, const Pose& actual) {
  const Eigen::Matrix3d dR = expected.linear().transpose() * actual.linear();
  const Eigen::Vector3d w(dR(2, 1) - dR(1, 2), dR(0, 2) - dR(2, 0), dR(1, 0) - dR(0, 1));
  const double angle = std::atan2(0.5 * w.norm(), 0.5 * (dR.trace() - 1.0));
  return {(expected.translation() - actual.translation()).norm(), angle};
}

#define EXPECT_POSE_NEAR(expected, actual)                 \
  do {                                                     \
    const PoseError e_ = pose_error((expected), (actual)); \
    EXPECT_LT(e_.position, kPosTol);                       \
    EXPECT_LT(e_.angle, kRotTol);                          \
  } while (0)

// Zero, the benchmark's initial configuration (robots.json / README section 2), and seeded
// uniform samples within the URDF limits. The initial configuration is written out here rather
// than read back from the model so the test does not depend on the loader for its inputs.
std::vector<Eigen::VectorXd> test_configurations(const RobotModel& model,
                                                 const Eigen::VectorXd& initial,
                                                 unsigned seed, int n_random) {
  std::vector<Eigen::VectorXd> qs;
  qs.push_back(Eigen::VectorXd::Zero(model.nq));
  qs.push_back(initial);
  qs.push_back(model.lower_limits());
  qs.push_back(model.upper_limits());
  std::mt19937 rng(seed);
  const Eigen::VectorXd lo = model.lower_limits(), hi = model.upper_limits();
  for (int k = 0; k < n_random; ++k) {
    Eigen::VectorXd q(model.nq);
    for (int i = 0; i < model.nq; ++i) q[i] = std::uniform_real_distribution<>(lo[i], hi[i])(rng);
    qs.push_back(q);
  }
  return qs;
}

// ---------------------------------------------------------------------------------------------
// Panda: Franka's modified (Craig) DH, T_i = RotX(alpha_{i-1}) TransX(a_{i-1}) RotZ(q_i)
// TransZ(d_i); flange = TransZ(0.107). Returns the 7 joint frames then the flange.
std::vector<Pose> panda_dh_frames(const Eigen::VectorXd& q) {
  const double a[7] = {0, 0, 0, 0.0825, -0.0825, 0, 0.088};
  const double d[7] = {0.333, 0, 0.316, 0, 0.384, 0, 0};
  const double alpha[7] = {0, -kPi / 2, kPi / 2, kPi / 2, -kPi / 2, kPi / 2, kPi / 2};
  std::vector<Pose> frames;
  Pose T = Pose::Identity();
  for (int i = 0; i < 7; ++i) {
    T = T * rot_x(alpha[i]) * trans_x(a[i]) * rot_z(q[i]) * trans_z(d[i]);
    frames.push_back(T);
  }
  frames.push_back(T * trans_z(0.107));
  return frames;
}

RobotModel load_panda() { return demoplan::load_urdf(kData + "/robots/franka_panda/panda.urdf"); }

TEST(KinematicsDh, PandaEveryLinkFrameMatchesModifiedDh) {
  const RobotModel model = load_panda();
  ASSERT_EQ(model.nq, 9);  // 7 arm joints + 2 fingers
  // DH frame i is URDF link panda_link{i}; the flange is panda_link8.
  std::vector<int> links;
  for (int i = 1; i <= 8; ++i) {
    links.push_back(model.link_index("panda_link" + std::to_string(i)));
    ASSERT_GE(links.back(), 0) << "panda_link" << i;
  }
  Eigen::VectorXd initial(9);
  initial << 0, -kPi / 4, 0, -3 * kPi / 4, 0, kPi / 2, kPi / 4, 0, 0;

  const auto qs = test_configurations(model, initial, 1234u, 8);
  ASSERT_GE(qs.size(), 8u);
  PoseVector poses;
  for (size_t c = 0; c < qs.size(); ++c) {
    const Eigen::VectorXd& q = qs[c];
    demoplan::forward_kinematics(model, q, Pose::Identity(), poses);
    ASSERT_EQ(poses.size(), model.links.size());
    const std::vector<Pose> dh = panda_dh_frames(q);
    for (int i = 0; i < 8; ++i) {
      SCOPED_TRACE("configuration " + std::to_string(c) + ", panda_link" + std::to_string(i + 1));
      EXPECT_POSE_NEAR(dh[i], poses[links[i]]);
      // The single-link path walks the chain separately; it must agree with the full pass.
      EXPECT_POSE_NEAR(dh[i], demoplan::link_pose(model, q, Pose::Identity(), links[i]));
    }
  }
}

TEST(KinematicsDh, PandaBasePoseIsAppliedOnTheLeft) {
  // World poses with a base B are B * (poses with the identity base).
  const RobotModel model = load_panda();
  Eigen::VectorXd q(9);
  q << 0.3, -0.5, 0.2, -2.0, 0.4, 1.8, -0.6, 0.01, 0.01;
  const Pose base = Pose(Eigen::Translation3d(0.5, -1.2, 0.75)) *
                    Pose(Eigen::AngleAxisd(2.0, Eigen::Vector3d(1, 2, 3).normalized()));
  PoseVector poses;
  demoplan::forward_kinematics(model, q, base, poses);
  const std::vector<Pose> dh = panda_dh_frames(q);
  for (int i = 0; i < 8; ++i) {
    const int link = model.link_index("panda_link" + std::to_string(i + 1));
    SCOPED_TRACE("panda_link" + std::to_string(i + 1));
    EXPECT_POSE_NEAR(base * dh[i], poses[link]);
    EXPECT_POSE_NEAR(base * dh[i], demoplan::link_pose(model, q, base, link));
  }
}

TEST(KinematicsDh, ComparisonIsSensitiveAtTheTolerance) {
  // Guard against a vacuous test: an error of 1e-5 rad in one joint must exceed the tolerance
  // (the flange is ~0.2 m from joint 6, so it moves ~2e-6 m as well).
  const RobotModel model = load_panda();
  Eigen::VectorXd q(9);
  q << 0.1, 0.2, 0.3, -1.0, 0.5, 1.0, 0.7, 0, 0;
  Eigen::VectorXd q_off = q;
  q_off[5] += 1e-5;
  const Pose urdf = demoplan::link_pose(model, q, Pose::Identity(), model.link_index("panda_link8"));
  const PoseError e = pose_error(panda_dh_frames(q_off)[7], urdf);
  EXPECT_GT(e.angle, kRotTol);
  EXPECT_GT(e.position, kPosTol);
}

// ---------------------------------------------------------------------------------------------
// UR5: standard DH, T_i = RotZ(q_i) TransZ(d_i) TransX(a_i) RotX(alpha_i).
//
// Relation to this URDF (old ur_description: shoulder_lift / wrist_1 origins rpy 0 pi/2 0,
// y offsets 0.13585, -0.1197, 0.093 whose sum is d4 = 0.10915):
//   T_urdf_tool0(q) = A * T_dh_06(q) * B, with A = RotZ(pi), B = identity, no joint offsets.
// Derivation at q = 0 (x0, y0, z0 = base_link axes):
//   DH: frame 1 = TransZ(d1) RotX(pi/2) has x1 = x0, y1 = z0, z1 = -y0. a2, a3 move along x1:
//     origin (a2 + a3, 0, d1) = (-0.81725, 0, d1). d4 along z3 = -y0, RotX(pi/2) gives
//     z4 = -z0; d5 along z4, RotX(-pi/2) gives z5 = -y0; d6 along z5. Flange origin
//     (-0.81725, -(d4 + d6), d1 - d5) = (-0.81725, -0.19145, d1 - d5), axes (x0, z0, -y0).
//   URDF: pan joint at (0, 0, d1); shoulder_lift RotY(pi/2) gives axes (-z0, y0, x0);
//     0.425 and 0.39225 go along x0 and the y offsets add up to +0.10915 along y0; wrist_1
//     RotY(pi/2) gives axes (-x0, y0, -z0); 0.09465 goes along -z0, 0.0823 along y0; tool0's
//     RotX(-pi/2) gives axes (-x0, z0, y0). Origin (0.81725, 0.19145, d1 - d5).
//   RotZ(pi) maps the DH flange (origin and axes (x0, z0, -y0) -> (-x0, z0, y0)) exactly onto
//   tool0, so B = I. For all q: the DH joint axes z0..z5 = (z0, -y0, -y0, -y0, -z0, -y0) map
//   under RotZ(pi) to (z0, y0, y0, y0, -z0, y0), exactly the URDF joint axes expressed in the
//   base (z, y, y, y, then wrist_2's z = -z0, then y) with the same sign, so theta_i = q_i.
struct Ur5Dh {
  std::vector<Pose> frames;  // DH frames 0..6 (frame 0 = DH base, frame 6 = flange)
};
Ur5Dh ur5_dh(const Eigen::VectorXd& q) {
  const double a[6] = {0, -0.425, -0.39225, 0, 0, 0};
  const double d[6] = {0.089159, 0, 0, 0.10915, 0.09465, 0.0823};
  const double alpha[6] = {kPi / 2, 0, 0, kPi / 2, -kPi / 2, 0};
  Ur5Dh out;
  Pose T = Pose::Identity();
  out.frames.push_back(T);
  for (int i = 0; i < 6; ++i) {
    T = T * rot_z(q[i]) * trans_z(d[i]) * trans_x(a[i]) * rot_x(alpha[i]);
    out.frames.push_back(T);
  }
  return out;
}
const Pose kUr5A = rot_z(kPi);
const Pose kUr5B = Pose::Identity();

RobotModel load_ur5() { return demoplan::load_urdf(kData + "/robots/ur5/ur5.urdf"); }

TEST(KinematicsDh, Ur5Tool0MatchesStandardDh) {
  const RobotModel model = load_ur5();
  ASSERT_EQ(model.nq, 8);  // 6 arm joints + 2 Panda fingers
  const int tool0 = model.link_index("tool0");  // this URDF has no ee_link
  ASSERT_GE(tool0, 0);
  Eigen::VectorXd initial(8);
  initial << 0, -3 * kPi / 4, kPi / 2, -kPi / 4, -kPi / 2, kPi / 4, 0, 0;

  const auto qs = test_configurations(model, initial, 5678u, 8);
  ASSERT_GE(qs.size(), 8u);
  PoseVector poses;
  for (size_t c = 0; c < qs.size(); ++c) {
    SCOPED_TRACE("configuration " + std::to_string(c));
    demoplan::forward_kinematics(model, qs[c], Pose::Identity(), poses);
    const Pose expected = kUr5A * ur5_dh(qs[c]).frames[6] * kUr5B;
    EXPECT_POSE_NEAR(expected, poses[tool0]);
    EXPECT_POSE_NEAR(expected, demoplan::link_pose(model, qs[c], Pose::Identity(), tool0));
  }
}

TEST(KinematicsDh, Ur5JointAxesLieOnDhZAxes) {
  // Intermediate URDF links are not DH frames, but each revolute axis is a line in space that
  // both models must agree on: URDF joint i turns about its axis through the child link origin,
  // DH joint i turns about z_{i-1} through o_{i-1}.
  const RobotModel model = load_ur5();
  const char* names[6] = {"shoulder_pan_joint", "shoulder_lift_joint", "elbow_joint",
                          "wrist_1_joint",      "wrist_2_joint",       "wrist_3_joint"};
  Eigen::VectorXd initial(8);
  initial << 0, -3 * kPi / 4, kPi / 2, -kPi / 4, -kPi / 2, kPi / 4, 0, 0;
  const auto qs = test_configurations(model, initial, 91011u, 6);
  PoseVector poses;
  for (size_t c = 0; c < qs.size(); ++c) {
    demoplan::forward_kinematics(model, qs[c], Pose::Identity(), poses);
    const Ur5Dh dh = ur5_dh(qs[c]);
    for (int i = 0; i < 6; ++i) {
      SCOPED_TRACE("configuration " + std::to_string(c) + ", " + names[i]);
      const int j = model.joint_index(names[i]);
      ASSERT_GE(j, 0);
      const Pose& child = poses[model.joints[j].child_link];
      const Eigen::Vector3d urdf_dir = child.linear() * model.joints[j].axis;
      const Eigen::Vector3d urdf_point = child.translation();
      const Pose dh_frame = kUr5A * dh.frames[i];
      const Eigen::Vector3d dh_dir = dh_frame.linear().col(2);
      EXPECT_LT((urdf_dir - dh_dir).norm(), kRotTol);  // same line, same sign
      EXPECT_LT((urdf_point - dh_frame.translation()).cross(dh_dir).norm(), kPosTol);
    }
  }
}

}  // namespace
