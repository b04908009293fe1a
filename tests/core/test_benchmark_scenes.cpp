// Every published task instance loads, and its start and goal are collision-free.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <fstream>

#include "core/demo/benchmark_scene.h"
#include "core/scene/collision_checker.h"

using namespace demoplan;

static const std::string kData = DEMOPLAN_DATA_DIR;

namespace {
MeshCache& meshes() {
  static MeshCache cache;
  return cache;
}

struct Instance {
  std::string task, robot;
  int pose;
};

std::vector<Instance> all_instances() {
  std::vector<Instance> out;
  for (const auto& t : list_benchmark_tasks(kData)) {
    const BenchmarkTask task = load_benchmark_task(kData, t);
    for (const auto& [robot, _] : task.robot_pose_files)
      for (int p : benchmark_pose_ids(task, robot)) out.push_back({t, robot, p});
  }
  return out;
}
}  // namespace

TEST(BenchmarkScenes, TheDataHasEveryPublishedInstance) {
  // gtamp README 4.2: shelf_0..2 and tunnel_0 with panda/ur5 poses 0..4 and kmr pose 0;
  // waiter_0 with kmr only; test_0 with panda pose 0.
  EXPECT_EQ(all_instances().size(), 4u * (5 + 5 + 1) + 1 + 1);
}

TEST(BenchmarkScenes, StartAndGoalAreCollisionFree) {
  for (const auto& in : all_instances()) {
    SCOPED_TRACE(in.task + " " + in.robot + " " + std::to_string(in.pose));
    const BenchmarkTask task = load_benchmark_task(kData, in.task);
    const Scene scene = build_benchmark_scene(task, in.robot, in.pose, {false, &meshes()});
    const CollisionChecker checker(scene);
    auto data = checker.make_data();
    const auto start = checker.collisions(benchmark_start_state(task, scene), data);
    const auto goal = checker.collisions(benchmark_goal_state(task, scene), data);
    if (in.task == "test_0") {
      // The dummy task of the benchmark's example puts both 0.1 x 0.2 x 0.8 cuboids at the
      // identity pose: they coincide with each other and stand in the tunnel's walls, and the
      // robot (identity base pose) stands in the tunnel. The data says "in collision".
      bool cuboids = false;
      for (const auto& p : start) cuboids |= p.first == "object/CUBOID_0.1_0.2_0.8" && p.second == p.first;
      EXPECT_TRUE(cuboids);
      EXPECT_FALSE(goal.empty());
      continue;
    }
    for (const auto& p : start) ADD_FAILURE() << "start: " << p.first << " / " << p.second;
    for (const auto& p : goal) ADD_FAILURE() << "goal: " << p.first << " / " << p.second;
  }
}

TEST(BenchmarkScenes, FurnitureUrdfMatchesTheTaskPoses) {
  for (const auto& name : list_benchmark_tasks(kData)) {
    const BenchmarkTask task = load_benchmark_task(kData, name);
    const Scene scene = build_benchmark_scene(task, task.robot_pose_files.begin()->first, 0, {false, &meshes()});
    for (size_t i = 0; i < task.furniture.size(); ++i) {
      // The generated URDF's main_link carries the furniture pose; all links share it.
      const auto& f = scene.furniture[i];
      const Pose& main = f.link_poses.back();
      SCOPED_TRACE(name + " " + f.name);
      EXPECT_LT((main.matrix() - task.furniture[i].pose.matrix()).cwiseAbs().maxCoeff(), 1e-9);
    }
  }
}

TEST(BenchmarkScenes, SupportBoxFollowsThePoseFile) {
  const BenchmarkTask task = load_benchmark_task(kData, "shelf_2");
  std::ifstream in(task.robot_pose_files.at("panda"));
  const auto json = nlohmann::json::parse(in);
  for (int p : benchmark_pose_ids(task, "panda")) {
    const Scene scene = build_benchmark_scene(task, "panda", p, {false, &meshes()});
    ASSERT_EQ(scene.furniture.size(), task.furniture.size() + 1);  // the box comes last
    const auto& box = scene.furniture.back();
    const auto& entry = json["support_box"][std::to_string(p)];
    const auto& size = std::get<BoxShape>(box.model.links[0].collisions[0].shape).size;
    for (int k = 0; k < 3; ++k) {
      // shelf_2/panda/3 has a negative height in the benchmark data: the box spans |h|.
      EXPECT_DOUBLE_EQ(size[k], std::abs(entry["size"][k].get<double>()));
      EXPECT_DOUBLE_EQ(box.link_poses[0](k, 3), entry["pose"][k][3].get<double>());
    }
  }
}

TEST(BenchmarkScenes, MobileRobotHasNoSupportBoxAndTheTrayIsNotAnObstacle) {
  const BenchmarkTask task = load_benchmark_task(kData, "waiter_0");
  const Scene scene = build_benchmark_scene(task, "kmr_iiwa", 0, {false, &meshes()});
  EXPECT_FALSE(scene.robot.fixed_base);
  EXPECT_EQ(scene.furniture.size(), task.furniture.size());
  ASSERT_EQ(scene.objects.size(), 3u);
  for (const auto& o : scene.objects) EXPECT_EQ(o.id.rfind("TRAY", 0), std::string::npos);
  EXPECT_EQ(scene.robot.model.nq, 12);
}

TEST(BenchmarkScenes, TunnelClosingWallsAreIgnoredByTheRobotOnly) {
  const BenchmarkTask task = load_benchmark_task(kData, "tunnel_0");
  const Scene scene = build_benchmark_scene(task, "panda", 0, {false, &meshes()});
  const auto& tunnel = scene.furniture[1];
  ASSERT_EQ(tunnel.kind, "tunnel");
  EXPECT_EQ(tunnel.robot_ignored_links.size(), 3u);
  const CollisionChecker checker(scene);
  auto data = checker.make_data();
  // An object moved into the closing wall above the tunnel collides with it.
  SceneState s = benchmark_start_state(task, scene);
  const int top = tunnel.model.link_index("top_sideB");
  ASSERT_GE(top, 0);
  const Eigen::Vector3d centre = tunnel.link_poses[top] * tunnel.model.links[top].collisions[0].origin.translation();
  s.objects[0].translation() = centre;
  bool hit = false;
  for (const auto& p : checker.collisions(s, data)) hit |= p.second.find("top_sideB") != std::string::npos;
  EXPECT_TRUE(hit);
}
