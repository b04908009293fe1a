// Time parameterization and the independent trajectory checker, on paths through real
// configurations of the benchmark scenes and on small synthetic paths.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>

#include "core/error.h"
#include "core/trajectory/double_s.h"
#include "core/trajectory/joint_limits.h"
#include "core/trajectory/time_parameterization.h"
#include "core/trajectory/trajectory_checker.h"
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

}  // namespace
}  // namespace demoplan
