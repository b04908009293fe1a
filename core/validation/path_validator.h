#pragma once
// The benchmark's success check re-derived from geometry, independent of the planner
// (gtamp README section 6): the path starts and ends where the task says, never collides,
// keeps every object grasped or placed, never moves a placed object; and the benchmark's
// metrics (path length, number of grasps).
#include <string>
#include <vector>

#include "core/demo/benchmark_task.h"
#include "core/demo/demonstration.h"
#include "core/path/path.h"
#include "core/scene/scene.h"

namespace demoplan {

// Where a valid path starts and ends.
struct ValidationTask {
  Eigen::VectorXd q_initial;  // the robot starts and ends here
  PoseList start_objects, goal_objects;
  std::string source;  // "benchmark subgoals" or "demonstration"
};
// The benchmark's own: the robot's initial configuration, subgoal columns 0 and S-1 (raw first
// and last frames for a task without subgoals).
ValidationTask validation_task(const BenchmarkTask& task, const Scene& scene);
// From a demonstration (e.g. estimated from the video): its first and last events' poses in the
// world (objects on a robot surface placed with the robot at its initial configuration).
ValidationTask validation_task(const Demonstration& demo, const Scene& scene);

struct ValidationOptions {
  double delta = 0.001;           // the benchmark's sampling of t in [0, 1]
  double max_joint_step = 0.01;   // also sample so that no two samples are further apart (rad)
  double error_identity = 0.001;
  double error_robot_distance = 0.0001;
  double error_grasp = 0.001;
  double placement_lower = -0.0001, placement_upper = 0.002;
};

struct PathLength {
  double robot = 0.0;               // rad (m for the KMR base)
  double object_translation = 0.0;  // m
  double object_rotation = 0.0;     // rad
};

// One grasp as the benchmark counts it: a (gripper, handle) pair that holds at sample t and did
// not at the previous sample.
struct CountedGrasp {
  double t = 0.0;
  std::string object, handle;
};

struct ValidationReport {
  bool valid = false;
  std::string message;  // the first failure, with its parameter t; "ok" when valid
  double failure_t = -1.0;
  PathLength length;    // on the benchmark's samples
  int grasps = 0;
  std::vector<CountedGrasp> counted_grasps;  // grasps.size() of them, in order
  // The path's own grasp actions: the gripper closes of the robot program. `grasps` counts more
  // when the gripper frame meets another handle on its way (a shallower handle on the approach
  // to a deeper one, as generated handles have): the benchmark counts that as a grasp too.
  int gripper_closes = 0;
  size_t samples = 0;
};

ValidationReport validate_path(const Scene& scene, const ValidationTask& task, const Path& path,
                               const ValidationOptions& options = {});

// "2 grasps", or "3 grasps as the benchmark counts them, 1 gripper close" when they differ.
std::string describe_grasps(int grasps, int gripper_closes);

}  // namespace demoplan
