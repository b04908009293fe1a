// The cell file: what is written is read back, and each kind of mistake is named by its field.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <random>

#include <gtest/gtest.h>

#include "core/cell/cell.h"
#include "core/cell/cell_scene.h"
#include "core/error.h"
#include "core/model/kinematics.h"
#include "core/project/new_project.h"
#include "core/project/project_scene.h"
#include "core/scene/collision_checker.h"
#include "core/scene/support.h"

namespace demoplan {
namespace {

namespace fs = std::filesystem;

const std::string kCells = std::string(DEMOPLAN_DATA_DIR) + "/../cells";

TEST(RpyFromRotation, InvertsRotationFromRpy) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-3.0, 3.0), p(-1.5, 1.5);
  for (int i = 0; i < 200; ++i) {
    const Eigen::Matrix3d R = rotation_from_rpy(u(rng), p(rng), u(rng));
    const Eigen::Vector3d rpy = rpy_from_rotation(R);
    EXPECT_LT((rotation_from_rpy(rpy.x(), rpy.y(), rpy.z()) - R).norm(), 1e-9);
  }
  // Gimbal lock: pitch +-90 degrees still gives back the rotation.
  const Eigen::Matrix3d lock = rotation_from_rpy(0.3, M_PI / 2, 0.7);
  const Eigen::Vector3d rpy = rpy_from_rotation(lock);
  EXPECT_LT((rotation_from_rpy(rpy.x(), rpy.y(), rpy.z()) - lock).norm(), 1e-9);
}

TEST(Cell, WhatIsWrittenIsReadBack) {
  const Cell cell = load_cell(kCells + "/ur5_workbench.json");
  ASSERT_EQ(cell.parts.size(), 2u);
  ASSERT_EQ(cell.furniture.size(), 3u);
  EXPECT_EQ(cell.robot.bundled, "ur5");
  EXPECT_TRUE(fs::path(cell.parts[0].mesh).is_absolute());
  EXPECT_TRUE(fs::exists(cell.parts[0].mesh));
  EXPECT_FALSE(cell.furniture[0].auto_supports);  // the pedestal: no supports
  EXPECT_TRUE(cell.furniture[0].supports.empty());

  const fs::path dir = fs::temp_directory_path() / "demoplan_test_cell";
  fs::create_directories(dir);
  Cell edited = cell;
  edited.parts[1].pose = pose_from_xyz_rpy({0.5, -0.1, 0.8}, {0.1, -0.2, 2.5});
  edited.parts[1].auto_handles = false;
  edited.parts[1].handles = {{"h", "base_link", pose_from_xyz_rpy({0, 0, 0.02}, {0, 1.5707963, 0}), 0.05}};
  edited.parts[1].markers = {{7, 0.025, pose_from_xyz_rpy({0, 0.02, 0}, {-1.5707963, 0, 0})}};
  const std::string file = (dir / "copy.json").string();
  save_cell(file, edited);
  const Cell back = load_cell(file);
  EXPECT_EQ(back.parts[0].mesh, cell.parts[0].mesh);  // relative paths follow the file
  EXPECT_LT((back.parts[1].pose.matrix() - edited.parts[1].pose.matrix()).norm(), 1e-9);
  ASSERT_EQ(back.parts[1].handles.size(), 1u);
  EXPECT_LT((back.parts[1].handles[0].pose.matrix() - edited.parts[1].handles[0].pose.matrix()).norm(), 1e-9);
  EXPECT_DOUBLE_EQ(back.parts[1].handles[0].clearance, 0.05);
  ASSERT_EQ(back.parts[1].markers.size(), 1u);
  EXPECT_EQ(back.parts[1].markers[0].id, 7);
  EXPECT_EQ(back.furniture[2].kind, CellFurniture::Kind::Mesh);
  EXPECT_DOUBLE_EQ(back.furniture[2].scale, 0.001);
  fs::remove_all(dir);
}

// Each broken cell, and the field its error names.
TEST(Cell, MistakesAreNamedByTheirField) {
  const Json good = read_json_file(kCells + "/ur5_workbench.json");
  auto expect_field = [&](const std::function<void(Json&)>& edit, const std::string& field) {
    Json j = good;
    edit(j);
    try {
      cell_from_json(j, kCells + "/broken.json");
      ADD_FAILURE() << "accepted a cell whose " << field << " is wrong";
    } catch (const InputError& e) {
      EXPECT_EQ(e.field(), field) << e.what();
    }
  };
  expect_field([](Json& j) { j["parts"][1]["name"] = "bracket"; }, "parts[1].name");
  expect_field([](Json& j) { j["robot"]["urdf"] = "x.urdf"; }, "robot");
  expect_field([](Json& j) { j["furniture"][1]["box"] = {1.0, -1.0, 1.0}; }, "furniture[1].box");
  expect_field([](Json& j) { j["furniture"][1]["mesh"] = "a.stl"; }, "furniture[1]");
  expect_field([](Json& j) { j["parts"][0]["scale"] = 0; }, "parts[0].scale");
  expect_field([](Json& j) { j["parts"][0]["pose"]["rpy"] = {1, 2}; }, "parts[0].pose.rpy");
  expect_field([](Json& j) { j["parts"][0]["handles"] = {{{"name", "a"}, {"pose", Json::object()}}}; },
               "parts[0].handles[0].clearance");
  expect_field([](Json& j) { j["format"] = "demoplan-project"; }, "format");
}

TEST(CellScene, ExampleCellsBuildAndStartCollisionFree) {
  for (const std::string name : {"ur5_workbench", "iiwa_shelf"}) {
    SCOPED_TRACE(name);
    const Cell cell = load_cell(kCells + "/" + name + ".json");
    CellSceneReport report;
    const Scene scene = build_cell_scene(cell, {.data_dir = DEMOPLAN_DATA_DIR}, &report);
    ASSERT_EQ(scene.objects.size(), cell.parts.size());
    for (const auto& p : report.parts) {
      EXPECT_TRUE(p.generated);
      EXPECT_GE(p.grasps.handles.size(), 4u) << p.part;
      EXPECT_GE(p.placements, 2) << p.part;
    }
    // Every part starts resting on a support, and nothing collides.
    const auto supports = support_polygons(scene);
    PoseVector links;
    forward_kinematics(scene.robot.model, scene.robot.initial_configuration, scene.robot.base, links);
    const SceneState start = cell_start_state(cell, scene);
    for (size_t o = 0; o < scene.objects.size(); ++o)
      EXPECT_TRUE(check_placement(scene, supports, links, static_cast<int>(o), start.objects[o]).placed) << scene.objects[o].id;
    const CollisionChecker checker(scene);
    auto data = checker.make_data();
    CollisionPair hit;
    EXPECT_FALSE(checker.in_collision(start, data, {}, &hit)) << hit.first << " / " << hit.second;
  }
}

TEST(CellScene, MissingFilesAndUnknownRobotsAreNamed) {
  Cell cell = load_cell(kCells + "/ur5_workbench.json");
  Cell missing = cell;
  missing.parts[1].mesh = kCells + "/parts/no_such.stl";
  try {
    build_cell_scene(missing, {.data_dir = DEMOPLAN_DATA_DIR});
    ADD_FAILURE() << "built a part from a missing mesh";
  } catch (const InputError& e) {
    EXPECT_EQ(e.field(), "parts[1].mesh");
  }
  Cell robot = cell;
  robot.robot.bundled = "r2d2";
  EXPECT_THROW(build_cell_scene(robot, {.data_dir = DEMOPLAN_DATA_DIR}), InputError);
}

TEST(CellProject, AProjectOnACellIsSavedAndReopenedWithItsScene) {
  const std::string cell_file = kCells + "/ur5_workbench.json";
  NewProject made = new_cell_project(DEMOPLAN_DATA_DIR, cell_file);
  EXPECT_TRUE(made.project.scene.is_cell());
  EXPECT_EQ(made.project.demonstration.object_ids, (std::vector<std::string>{"bracket", "flanged_cylinder"}));
  EXPECT_TRUE(made.project.demonstration.events.empty());
  const fs::path dir = fs::temp_directory_path() / "demoplan_test_cell_project";
  fs::create_directories(dir);
  const std::string file = (dir / "p.demoplan").string();
  save_project(file, made.project);
  EXPECT_NE(read_json_file(file)["scene"]["cell"].get<std::string>().find("ur5_workbench.json"), std::string::npos);
  const Project back = load_project(file);
  EXPECT_EQ(back.scene, made.project.scene);
  const ReferencedScene loaded = load_referenced_scene(back.scene, DEMOPLAN_DATA_DIR);
  EXPECT_EQ(loaded.task, nullptr);
  ASSERT_EQ(loaded.scene->objects.size(), 2u);
  EXPECT_EQ(loaded.scene->robot.name, "ur5");
  EXPECT_EQ(back.scene.describe(), "ur5_workbench.json");
  fs::remove_all(dir);
}

}  // namespace
}  // namespace demoplan
