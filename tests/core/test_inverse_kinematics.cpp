// Damped least squares IK: reachable targets are met to 1e-6 within the limits; unreachable
// ones are reported as failures, never as approximate answers.
#include <gtest/gtest.h>

#include "core/model/inverse_kinematics.h"
#include "core/model/kinematics.h"

using namespace demoplan;

static const std::string kData = DEMOPLAN_DATA_DIR;

namespace {

Eigen::VectorXd random_q(const RobotModel& m, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(0, 1);
  Eigen::VectorXd q(m.nq);
  const Eigen::VectorXd lo = m.lower_limits(), hi = m.upper_limits();
  for (int i = 0; i < m.nq; ++i) q[i] = lo[i] + u(rng) * (hi[i] - lo[i]);
  return q;
}

IkSolver hand_solver(const RobotModel& m, int arm_joints_from, int arm_joints_to) {
  IkProblem p;
  p.model = &m;
  p.link = m.link_index("panda_hand");
  p.link_T_frame.translation() = Eigen::Vector3d(0, 0, 0.12);
  for (int i = arm_joints_from; i < arm_joints_to; ++i) p.active.push_back(i);
  return IkSolver(p);
}

void expect_reaches_random_targets(const RobotModel& m, const IkSolver& solver, double min_rate) {
  std::mt19937_64 rng(42);
  int ok = 0;
  const int n = 200;
  for (int k = 0; k < n; ++k) {
    const Eigen::VectorXd truth = random_q(m, rng);
    const Pose target = solver.frame_pose(truth);
    const IkResult r = solver.solve(target, random_q(m, rng), rng);
    if (!r.success) {
      EXPECT_TRUE(r.position_error >= 1e-6 || r.rotation_error >= 1e-6);  // honest failure
      continue;
    }
    ++ok;
    EXPECT_LT(r.position_error, 1e-6);
    EXPECT_LT(r.rotation_error, 1e-6);
    const Pose reached = solver.frame_pose(r.q);
    EXPECT_LT((reached.translation() - target.translation()).norm(), 1e-6);
    EXPECT_LT(log3(reached.linear().transpose() * target.linear()).norm(), 1e-6);
    EXPECT_TRUE(m.within_limits(r.q));
  }
  std::printf("IK: %d of %d random reachable targets met\n", ok, n);
  EXPECT_GE(ok, static_cast<int>(min_rate * n));
}

}  // namespace

TEST(InverseKinematics, PandaReachesTargetsItCanReach) {
  const RobotModel m = load_urdf(kData + "/robots/franka_panda/panda.urdf");
  expect_reaches_random_targets(m, hand_solver(m, 0, 7), 0.95);
}

TEST(InverseKinematics, KmrUsesItsMobileBase) {
  const RobotModel m = load_urdf(kData + "/robots/kuka_kmr_iiwa/kuka_kmr_iiwa.urdf");
  expect_reaches_random_targets(m, hand_solver(m, 0, 10), 0.95);
}

TEST(InverseKinematics, UnreachableTargetFailsHonestly) {
  const RobotModel m = load_urdf(kData + "/robots/franka_panda/panda.urdf");
  const IkSolver solver = hand_solver(m, 0, 7);
  std::mt19937_64 rng(1);
  Pose far = Pose::Identity();
  far.translation() << 2.0, 0.0, 0.5;  // the Panda reaches about 0.86 m
  const IkResult r = solver.solve(far, Eigen::VectorXd::Zero(m.nq), rng);
  EXPECT_FALSE(r.success);
  EXPECT_GT(r.position_error, 1.0);
  EXPECT_TRUE(m.within_limits(r.q));
}

TEST(InverseKinematics, InactiveJointsKeepTheSeedValues) {
  const RobotModel m = load_urdf(kData + "/robots/franka_panda/panda.urdf");
  const IkSolver solver = hand_solver(m, 0, 7);
  std::mt19937_64 rng(5);
  Eigen::VectorXd seed = random_q(m, rng);
  seed[7] = 0.031, seed[8] = 0.017;  // fingers
  const IkResult r = solver.solve(solver.frame_pose(random_q(m, rng)), seed, rng);
  ASSERT_TRUE(r.success);
  EXPECT_EQ(r.q[7], 0.031);
  EXPECT_EQ(r.q[8], 0.017);
}
