// Time parameterization and the independent trajectory checker, on paths through real
// configurations of the benchmark scenes and on small synthetic paths.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>

#include "core/error.h"
#include <map>
#include "core/trajectory/double_s.h"
#include "core/trajectory/joint_limits.h"
#include "core/trajectory/time_parameterization.h"
#include "core/trajectory/trajectory_checker.h"
#include "core/validation/trajectory_collisions.h"
#include "tests/core/transition_path.h"

namespace demoplan {
namespace {

using testing_support::benchmark_transition_path;
using testing_support::BenchmarkPathCase;

const BenchmarkPathCase& benchmark_case(const std::string& task, const std::string& robot) {
  static std::map<std::string, BenchmarkPathCase> cache;
  const std::string key = task + "/" + robot;
  auto it = cache.find(key);
  if (it == cache.end()) it = cache.emplace(key, benchmark_transition_path(DEMOPLAN_DATA_DIR, task, robot)).first;
  return it->second;
}

// ---------------------------------------------------------------------------------------------
// The double-S profile on its own.

TEST(DoubleS, ReachesTheEndWithinLimits) {
  const DoubleSLimits l{2.0, 5.0, 50.0};
  for (double h : {0.001, 0.05, 0.3, 1.0, 4.0})
    for (double v0 : {0.0, 0.4, 2.0})
      for (double v1 : {0.0, 1.0, 2.0}) {
        if (!double_s_feasible(h, v0, v1, l)) continue;
        SCOPED_TRACE("h " + std::to_string(h) + " v0 " + std::to_string(v0) + " v1 " + std::to_string(v1));
        const DoubleS s = plan_double_s(h, v0, v1, l);
        const DoubleSState end = s.at(s.duration());
        EXPECT_NEAR(end.p, h, 1e-9);
        EXPECT_NEAR(end.v, v1, 1e-9);
        EXPECT_NEAR(end.a, 0.0, 1e-9);
        EXPECT_NEAR(s.at(0).v, v0, 1e-12);
        double prev_p = 0, prev_a = 0;
        for (int i = 1; i <= 2000; ++i) {
          const double t = s.duration() * i / 2000;
          const DoubleSState st = s.at(t);
          EXPECT_LE(st.v, l.velocity * (1 + 1e-9));
          EXPECT_GE(st.v, -1e-9);
          EXPECT_LE(std::abs(st.a), l.acceleration * (1 + 1e-9));
          EXPECT_LE(std::abs(st.a - prev_a) / (s.duration() / 2000), l.jerk * (1 + 1e-6));
          EXPECT_GE(st.p, prev_p - 1e-12);  // never backwards
          prev_p = st.p, prev_a = st.a;
        }
      }
}

TEST(DoubleS, LongRestToRestMoveTakesTheTextbookTime) {
  // Cruise reached, full acceleration reached: T = h/v + v/a + a/j.
  const DoubleSLimits l{2.0, 5.0, 50.0};
  const DoubleS s = plan_double_s(4.0, 0, 0, l);
  EXPECT_NEAR(s.duration(), 4.0 / 2.0 + 2.0 / 5.0 + 5.0 / 50.0, 1e-9);
}

// ---------------------------------------------------------------------------------------------
// Benchmark paths.

struct Instance {
  std::string task, robot;
};

class BenchmarkTrajectory : public ::testing::TestWithParam<Instance> {};

TEST_P(BenchmarkTrajectory, WithinLimitsThroughEveryWaypoint) {
  const auto& [task, robot] = GetParam();
  const BenchmarkPathCase& c = benchmark_case(task, robot);
  const JointLimitSet limits = trajectory_limits(c.scene.robot.model);
  const Trajectory tr = time_parameterize(c.path, limits);
  ASSERT_EQ(tr.waypoint_times.size(), c.path.waypoints.size());
  EXPECT_EQ(tr.safety_scale, 1.0);
  const auto samples = tr.sample(250.0);
  const CheckReport r = check_trajectory(samples, c.path, limits);
  EXPECT_TRUE(r.ok) << (r.violations.empty() ? "" : r.violations.front());
  EXPECT_LE(r.peak_velocity_ratio, 1.0);
  EXPECT_GT(r.peak_velocity_ratio, 0.3);
  EXPECT_LE(r.peak_acceleration_ratio, 1.0);
  // Each waypoint at its knot time, exactly.
  for (size_t k = 0; k < c.path.waypoints.size(); ++k)
    EXPECT_LT((tr.motion.at(tr.waypoint_times[k]).q - c.path.waypoints[k].q).cwiseAbs().maxCoeff(), 1e-12) << k;
  std::printf("[ info ] %s %s: %zu waypoints, %.3f s (trapezoid %.3f s, ratio %.2f), peak v %.2f a %.2f, "
              "deviation %.4f\n",
              task.c_str(), robot.c_str(), c.path.waypoints.size(), tr.duration, tr.trapezoid_duration,
              tr.trapezoid_duration / tr.duration, r.peak_velocity_ratio, r.peak_acceleration_ratio,
              r.max_path_deviation);
}

INSTANTIATE_TEST_SUITE_P(Robots, BenchmarkTrajectory,
                         ::testing::Values(Instance{"shelf_1", "panda"}, Instance{"tunnel_0", "ur5"},
                                           Instance{"waiter_0", "kmr_iiwa"}),
                         [](const auto& info) { return info.param.task + "_" + info.param.robot; });


// ---------------------------------------------------------------------------------------------
// The checker rejects what breaks the contract.

struct Checked {
  const BenchmarkPathCase* c;
  JointLimitSet limits;
  std::vector<TrajectorySample> samples;
};

Checked checked_panda() {
  Checked k;
  k.c = &benchmark_case("shelf_1", "panda");
  k.limits = trajectory_limits(k.c->scene.robot.model);
  k.samples = time_parameterize(k.c->path, k.limits).sample(250.0);
  return k;
}

bool mentions(const CheckReport& r, const std::string& what) {
  for (const auto& v : r.violations)
    if (v.find(what) != std::string::npos) return true;
  return false;
}

TEST(TrajectoryChecker, RejectsAVelocityBeyondItsLimit) {
  Checked k = checked_panda();
  auto& s = k.samples[k.samples.size() / 2];
  s.v[1] = k.limits.velocity[1] * 1.01;
  const CheckReport r = check_trajectory(k.samples, k.c->path, k.limits);
  EXPECT_FALSE(r.ok);
  EXPECT_TRUE(mentions(r, "panda_joint2: velocity")) << r.violations.front();
}

TEST(TrajectoryChecker, RejectsAnAccelerationOrJerkBeyondItsLimit) {
  Checked k = checked_panda();
  k.samples[k.samples.size() / 3].a[0] = k.limits.acceleration[0] * 1.05;
  const CheckReport r = check_trajectory(k.samples, k.c->path, k.limits);
  EXPECT_FALSE(r.ok);
  EXPECT_TRUE(mentions(r, "panda_joint1: acceleration"));
  // A jump in acceleration within the acceleration limit, too steep for the jerk limit.
  const auto& c = benchmark_case("shelf_1", "panda");
  auto fine = time_parameterize(c.path, k.limits).sample(1000.0);
  size_t i = 1;
  while (std::abs(fine[i - 1].a[1]) > 0.5) ++i;
  fine[i].a[1] = fine[i - 1].a[1] + 1.5 * k.limits.jerk[1] * (fine[i].t - fine[i - 1].t);
  EXPECT_TRUE(mentions(check_trajectory(fine, c.path, k.limits), "panda_joint2: jerk"));
}

TEST(TrajectoryChecker, RejectsAPositionBeyondItsLimitOrAJump) {
  Checked k = checked_panda();
  k.samples[10].q[3] = k.limits.upper[3] + 0.01;
  const CheckReport r = check_trajectory(k.samples, k.c->path, k.limits);
  EXPECT_FALSE(r.ok);
  EXPECT_TRUE(mentions(r, "panda_joint4: position"));
  EXPECT_TRUE(mentions(r, "velocities integrate"));  // stored velocities do not explain the move
}

TEST(TrajectoryChecker, RejectsATrajectoryThatSkipsAWaypoint) {
  Checked k = checked_panda();
  // A path with one more waypoint the trajectory never visits.
  Path other = k.c->path;
  Waypoint extra = other.waypoints[2];
  extra.q[0] += 0.05;
  other.waypoints.insert(other.waypoints.begin() + 3, extra);
  const CheckReport r = check_trajectory(k.samples, other, k.limits);
  EXPECT_FALSE(r.ok);
  EXPECT_TRUE(mentions(r, "waypoint 3 is never reached")) << r.violations.front();
  // And one whose waypoints come in another order.
  Path swapped = k.c->path;
  std::swap(swapped.waypoints[1], swapped.waypoints[5]);
  EXPECT_FALSE(check_trajectory(k.samples, swapped, k.limits).ok);
}

TEST(TrajectoryChecker, RejectsMotionAtAGraspOrAWrongGripperState) {
  Checked k = checked_panda();
  const CheckReport good = check_trajectory(k.samples, k.c->path, k.limits);
  ASSERT_TRUE(good.ok);
  size_t grasp = 0;
  while (k.c->path.waypoints[grasp].action != GripperAction::Grasp) ++grasp;
  auto moving = k.samples;
  moving[good.waypoint_samples[grasp]].v[0] = 0.01;
  EXPECT_TRUE(mentions(check_trajectory(moving, k.c->path, k.limits), "must be reached at rest"));
  auto open = k.samples;
  open[good.waypoint_samples[grasp] + 1].gripper_closed = false;
  EXPECT_TRUE(mentions(check_trajectory(open, k.c->path, k.limits), "gripper should be closed"));
}

// ---------------------------------------------------------------------------------------------
// Limits and bad input.

TEST(TrajectoryLimits, FrankaTableAndOverrides) {
  const RobotModel& panda = benchmark_case("shelf_1", "panda").scene.robot.model;
  const JointLimitSet l = trajectory_limits(panda);
  EXPECT_EQ(l.names[1], "panda_joint2");
  EXPECT_DOUBLE_EQ(l.velocity[1], 2.175);
  EXPECT_DOUBLE_EQ(l.acceleration[1], 7.5);
  EXPECT_DOUBLE_EQ(l.jerk[1], 3750);
  EXPECT_TRUE(l.jerk_published[1]);
  LimitOverrides o;
  o.acceleration["panda_joint2"] = 2.0;
  o.velocity_scale = 0.5;
  const JointLimitSet slow = trajectory_limits(panda, o);
  EXPECT_DOUBLE_EQ(slow.acceleration[1], 2.0);
  EXPECT_DOUBLE_EQ(slow.velocity[0], 2.175 * 0.5);
  // The UR5's URDF says 3.15 rad/s; the datasheet's 180 deg/s caps it.
  const JointLimitSet ur5 = trajectory_limits(benchmark_case("tunnel_0", "ur5").scene.robot.model);
  EXPECT_NEAR(ur5.velocity[0], M_PI, 1e-12);
  // Slower limits, longer motion, still within them.
  const auto& c = benchmark_case("shelf_1", "panda");
  const Trajectory fast = time_parameterize(c.path, l), slower = time_parameterize(c.path, slow);
  EXPECT_GT(slower.duration, fast.duration * 1.2);
  EXPECT_TRUE(check_trajectory(slower.sample(100.0), c.path, slow).ok);
}

TEST(TrajectoryLimits, RobotWithoutVelocityLimitsIsAClearError) {
  RobotModel m = benchmark_case("shelf_1", "panda").scene.robot.model;
  for (auto& j : m.joints)
    if (j.name == "panda_joint3") j.limits.velocity = 0;
  try {
    trajectory_limits(m);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("panda_joint3"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("velocity"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("panda.urdf"), std::string::npos) << e.what();
  }
}

TEST(TrajectoryLimits, PathBeyondAJointLimitIsAClearError) {
  const auto& c = benchmark_case("shelf_1", "panda");
  const JointLimitSet l = trajectory_limits(c.scene.robot.model);
  Path bad = c.path;
  bad.waypoints[4].q[1] = 1.9;  // panda_joint2 stops at 1.8326
  TimingOptions o;
  o.source = "bad.json";
  try {
    time_parameterize(bad, l, o);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), "bad.json");
    EXPECT_EQ(e.field(), "waypoints[4].q[1]");
    EXPECT_NE(std::string(e.what()).find("panda_joint2 = 1.9 is beyond its limit"), std::string::npos) << e.what();
  }
}

// ---------------------------------------------------------------------------------------------
// A small synthetic path: a corner is blended, passed exactly, and every joint stays between the
// values of the waypoints around it.

TEST(TimeParameterization, BlendsPassExactlyAndMonotonically) {
  const RobotModel& m = benchmark_case("shelf_1", "panda").scene.robot.model;
  const JointLimitSet l = trajectory_limits(m);
  Path p;
  p.joint_names = l.names;
  const Eigen::VectorXd q0 = (l.lower + l.upper) / 2;
  Eigen::VectorXd q1 = q0, q2 = q0, q3 = q0;
  q1[0] += 0.6, q1[1] += 0.3;
  q2 = q1, q2[0] += 0.5, q2[1] += 0.2, q2[2] += 0.05;  // a gentle corner at q1
  q3 = q2, q3[0] += 0.3, q3[1] -= 0.2, q3[2] += 0.3;  // joint 2 turns back at q2
  for (const auto& q : {q0, q1, q2, q3}) p.waypoints.push_back({q, {}, 0, "P0", GripperAction::None, -1, false});
  const Trajectory tr = time_parameterize(p, l);
  EXPECT_FALSE(tr.stops[1]);
  EXPECT_GT(tr.motion.at(tr.waypoint_times[1]).v.norm(), 0.1);  // passes without stopping
  EXPECT_LT(tr.duration, tr.trapezoid_duration);
  const auto samples = tr.sample(1000.0);
  EXPECT_TRUE(check_trajectory(samples, p, l).ok);
  for (const auto& s : samples)
    for (size_t k = 0; k + 1 < p.waypoints.size(); ++k) {
      if (s.t < tr.waypoint_times[k] || s.t > tr.waypoint_times[k + 1]) continue;
      for (long j = 0; j < l.size(); ++j) {
        const double lo = std::min(p.waypoints[k].q[j], p.waypoints[k + 1].q[j]);
        const double hi = std::max(p.waypoints[k].q[j], p.waypoints[k + 1].q[j]);
        EXPECT_GE(s.q[j], lo - 1e-12) << "t " << s.t << " joint " << j;
        EXPECT_LE(s.q[j], hi + 1e-12) << "t " << s.t << " joint " << j;
      }
    }
}

// The blends cut the path's corners. Where a cut touches the scene the robot rests at that corner
// instead, and the retimed trajectory's blends are all collision-free.
TEST(TrajectoryClearance, BlendsThatTouchTheSceneBecomeRests) {
  int touched = 0;
  for (const auto& [task, robot] : {std::pair{"shelf_1", "panda"}, std::pair{"tunnel_0", "ur5"}}) {
    const BenchmarkPathCase& c = benchmark_case(task, robot);
    const JointLimitSet limits = trajectory_limits(c.scene.robot.model);
    const CollisionChecker checker(c.scene);
    TimingOptions wide;
    wide.blend_length = 0.5;
    const Trajectory blended = time_parameterize(c.path, limits, wide);
    const TrajectoryCollision before = first_trajectory_collision(c.scene, checker, c.path, blended);
    const ClearTrajectory clear = time_parameterize_clear(c.scene, checker, c.path, limits, wide);
    EXPECT_TRUE(first_trajectory_collision(c.scene, checker, c.path, clear.trajectory).free);
    EXPECT_EQ(before.free, clear.rests_added.empty());
    if (!before.free) {
      ++touched;
      EXPECT_EQ(clear.rests_added.front(), before.waypoint);
      EXPECT_TRUE(clear.trajectory.stops[before.waypoint]);
      EXPECT_LT(clear.trajectory.blends.size(), blended.blends.size());
    }
    EXPECT_TRUE(check_trajectory(clear.trajectory.sample(250.0), c.path, limits).ok);
    std::printf("[ info ] %s %s: %zu blends, %zu became rests (first at %.3f s: %s / %s)\n", task, robot,
                blended.blends.size(), clear.rests_added.size(), before.time, before.pair.first.c_str(),
                before.pair.second.c_str());
  }
  EXPECT_GT(touched, 0);  // the approach corners near the parts make some blends touch
}

// A corner where one joint barely moves on both sides (as shortened paths have them): its share
// of a blend piece rounds away against its position, yet the piece must keep a positive duration.
TEST(TimeParameterization, CornerWithABarelyMovingJoint) {
  const JointLimitSet l = trajectory_limits(benchmark_case("shelf_1", "panda").scene.robot.model);
  Path p;
  p.joint_names = l.names;
  const Eigen::VectorXd q0 = (l.lower + l.upper) / 2;
  Eigen::VectorXd step = Eigen::VectorXd::Zero(l.size()), turn = step;
  step[0] = 0.4, step[1] = 0.2;
  turn[0] = 0.3, turn[1] = 0.25;
  Eigen::VectorXd q1 = q0 + step, q2 = q1 + turn;
  q1[3] = std::nextafter(q0[3], 10.0);  // one ulp on either side of the corner
  q2[3] = std::nextafter(q1[3], 10.0);
  for (const auto& q : {q0, q1, q2}) p.waypoints.push_back({q, {}, 0, "P0", GripperAction::None, -1, false});
  const Trajectory tr = time_parameterize(p, l);
  EXPECT_FALSE(tr.stops[1]);
  const CheckReport r = check_trajectory(tr.sample(500.0), p, l);
  EXPECT_TRUE(r.ok) << (r.violations.empty() ? "" : r.violations.front());
}

}  // namespace
}  // namespace demoplan
