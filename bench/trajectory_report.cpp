// The numbers of docs/benchmarks.md "Trajectories": for each benchmark task and robot, a path
// through real transition configurations (tests/core/transition_path.h), time-parameterized,
// checked, and compared with per-segment trapezoids. Not a timing benchmark: durations are of
// the robot's motion. Usage: trajectory_report [--verbose TASK ROBOT]
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "core/trajectory/time_parameterization.h"
#include "core/trajectory/trajectory_checker.h"
#include "core/trajectory/trapezoid.h"
#include "tests/core/transition_path.h"

using namespace demoplan;

namespace {

void report(const std::string& task, const std::string& robot, bool verbose) {
  const auto c = testing_support::benchmark_transition_path(DEMOPLAN_DATA_DIR, task, robot);
  const JointLimitSet limits = trajectory_limits(c.scene.robot.model);
  const Trajectory tr = time_parameterize(c.path, limits);
  const CheckReport r = check_trajectory(tr.sample(1000.0), c.path, limits);
  int stops = 0;
  for (char s : tr.stops) stops += s;
  std::printf("| %-8s | %-8s | %3zu | %2d | %6.2f | %6.2f | %4.2f | %4.2f | %4.2f | %.1e | %s |\n", task.c_str(),
              robot.c_str(), c.path.waypoints.size(), stops, tr.duration, tr.trapezoid_duration,
              tr.trapezoid_duration / tr.duration, r.peak_velocity_ratio, r.peak_acceleration_ratio,
              r.max_path_deviation, r.ok ? "ok" : r.violations.front().c_str());
  if (!verbose) return;
  for (size_t k = 0; k < c.path.waypoints.size(); ++k) {
    const double dt = k ? tr.waypoint_times[k] - tr.waypoint_times[k - 1] : 0;
    const double len = k ? (c.path.waypoints[k].q - c.path.waypoints[k - 1].q).norm() : 0;
    const double v = tr.motion.at(tr.waypoint_times[k]).v.norm();
    Path pair = c.path;
    pair.waypoints = k ? std::vector<Waypoint>{c.path.waypoints[k - 1], c.path.waypoints[k]} : std::vector<Waypoint>{};
    std::printf("  %3zu %s t %8.3f dt %7.3f (trapezoid %7.3f) length %7.4f speed %7.4f\n", k, tr.stops[k] ? "stop" : "pass",
                tr.waypoint_times[k], dt, trapezoid_duration(pair, limits), len, v);
  }
  std::printf("  safety scale %.4f\n", tr.safety_scale);
}

}  // namespace

int main(int argc, char** argv) {
  if (argc == 4 && std::strcmp(argv[1], "--verbose") == 0) {
    report(argv[2], argv[3], true);
    return 0;
  }
  std::printf("| task | robot | waypoints | stops | duration s | trapezoid s | trapezoid/ours | peak v/limit | "
              "peak a/limit | max deviation (rad) | check |\n|---|---|---|---|---|---|---|---|---|---|---|\n");
  for (const char* robot : {"panda", "ur5", "kmr_iiwa"})
    for (const char* task : {"shelf_0", "shelf_1", "shelf_2", "tunnel_0", "waiter_0"}) {
      if (std::string(task) == "waiter_0" && std::string(robot) != "kmr_iiwa") continue;
      report(task, robot, false);
    }
  return 0;
}
