#pragma once
// Builds the Scene of a benchmark task instance (task, robot, robot pose id) the way the
// benchmark's collision model does (gtamp README sections 2, 5 and 6).
#include <string>
#include <vector>

#include "core/demo/benchmark_task.h"
#include "core/scene/scene.h"

namespace demoplan {

// One entry of gtamp/robots/robots.json.
struct BenchmarkRobot {
  std::string name;
  std::string urdf, srdf;  // absolute
  bool fixed_base = true;
  Eigen::VectorXd initial_configuration;
  // The footprint of the support box under a fixed robot, in the base frame (README 5.1).
  Eigen::Vector2d footprint_size = Eigen::Vector2d::Zero(), footprint_offset = Eigen::Vector2d::Zero();
};

BenchmarkRobot load_benchmark_robot(const std::string& data_dir, const std::string& name);
std::vector<std::string> list_benchmark_robots(const std::string& data_dir);

// Robot pose ids the task publishes for this robot (empty when it has none).
std::vector<int> benchmark_pose_ids(const BenchmarkTask& task, const std::string& robot);

struct SceneLoadOptions {
  bool load_visual_meshes = false;
  MeshCache* mesh_cache = nullptr;
};

// The robot base pose `pose_id` of the task's pose file for `robot`. Throws InputError.
Pose benchmark_robot_pose(const BenchmarkTask& task, const std::string& robot, int pose_id);

// The robot at the pose `pose_id` of the task's pose file, the task's furniture plus the support
// box under a fixed robot, and the task's planning objects (trays excluded). Throws InputError.
Scene build_benchmark_scene(const BenchmarkTask& task, const std::string& robot, int pose_id,
                            const SceneLoadOptions& options = {});

// The kind of the support box among the scene's furniture.
inline constexpr const char* kSupportBoxKind = "support_box";

// The support box under a fixed robot at `base` (README 5.1): from the highest contact surface
// of the furniture under the base, or the floor, up to the base; `size` may have a negative
// height exactly as the benchmark computes it.
struct SupportBox {
  Pose pose = Pose::Identity();
  Eigen::Vector3d size = Eigen::Vector3d::Zero();
};
SupportBox support_box_at(const Scene& scene, const BenchmarkRobot& robot, const Pose& base);

// Stands the scene's robot at `base`: a fixed robot's support box made again for it (a base the
// task does not publish, as the placement search tries). Throws InputError for a mobile robot,
// whose base moves through its own joints.
void move_benchmark_robot(Scene& scene, const BenchmarkRobot& robot, const Pose& base);

// The robot's initial configuration with the objects at the first (start) or last (goal)
// subgoal column; tasks without subgoals use the first and last raw frames.
SceneState benchmark_start_state(const BenchmarkTask& task, const Scene& scene);
SceneState benchmark_goal_state(const BenchmarkTask& task, const Scene& scene);

}  // namespace demoplan
