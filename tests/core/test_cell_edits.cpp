// The edits of the cell editor, without the GUI: a starter cell that loads collision-free for a
// fixed and a mobile robot, names that do not clash, a part from an STL put down on a free spot
// of the table (the same spot for the same cell, clear of the parts already there), and the
// demonstration kept in step when parts come and go; the robot replaced by a bundled one or by a
// URDF + SRDF laid out as a ROS package (its package:// folder found).
#include <gtest/gtest.h>
#include <algorithm>
#include <fstream>
#include <sstream>

#include "core/cell/cell_edits.h"
#include "core/error.h"
#include "core/model/package_paths.h"
#include "core/placement/base_clearance.h"
#include "core/scene/collision_checker.h"
#include "tests/support/box_stl.h"
#include "tests/support/temp_folder.h"

namespace demoplan {
namespace {

bool start_collides(const Cell& cell) {
  const Scene scene = build_cell_scene(cell, {.data_dir = DEMOPLAN_DATA_DIR});
  const CollisionChecker checker(scene);
  CollisionData data = checker.make_data();
  return checker.in_collision(cell_start_state(cell, scene), data);
}

TEST(CellEdits, StarterCellsLoadCollisionFree) {
  test::TempFolder dir("demoplan_cell_edits");
  for (const char* robot : {"panda", "ur5", "kmr_iiwa"}) {
    const Cell cell = starter_cell(dir.file(std::string(robot) + ".json"), robot, DEMOPLAN_DATA_DIR);
    EXPECT_EQ(cell.robot.bundled, robot);
    EXPECT_EQ(cell.robot.mobile, std::string(robot) == "kmr_iiwa");
    EXPECT_EQ(cell.furniture.size(), cell.robot.mobile ? 1u : 2u) << robot;
    EXPECT_FALSE(start_collides(cell)) << robot;
    save_cell(cell.file, cell);
    EXPECT_EQ(load_cell(cell.file).furniture.size(), cell.furniture.size());
  }
  EXPECT_THROW(starter_cell(dir.file("x.json"), "no_such_robot", DEMOPLAN_DATA_DIR), InputError);
}

TEST(CellEdits, NamesDoNotClash) {
  Cell cell = starter_cell("/tmp/c.json", "ur5", DEMOPLAN_DATA_DIR);
  EXPECT_EQ(unique_cell_name(cell, "box"), "box");
  EXPECT_EQ(unique_cell_name(cell, "table"), "table 2");
  cell.furniture.back().name = "table 2";
  cell.furniture.push_back(cell.furniture.back());
  cell.furniture.back().name = "table";
  EXPECT_EQ(unique_cell_name(cell, "table"), "table 3");
}

TEST(CellEdits, PartsArePutDownOnFreeSpotsTheSameWayEachTime) {
  test::TempFolder dir("demoplan_cell_edits");
  test::write_box_stl(dir.path() / "block.stl", 40, 30, 20);
  EXPECT_EQ(guess_unit_scale(dir.file("block.stl")), 0.001);
  Cell cell = starter_cell(dir.file("cell.json"), "ur5", DEMOPLAN_DATA_DIR);
  const CellSceneOptions options{.data_dir = DEMOPLAN_DATA_DIR};
  Cell again = cell;
  EXPECT_EQ(add_part_from_mesh(cell, dir.file("block.stl"), 0.001, options), 0);
  EXPECT_EQ(add_part_from_mesh(again, dir.file("block.stl"), 0.001, options), 0);
  EXPECT_TRUE(cell.parts[0].pose.isApprox(again.parts[0].pose, 1e-12));
  EXPECT_EQ(add_part_from_mesh(cell, dir.file("block.stl"), 0.001, options), 1);
  EXPECT_EQ(cell.parts[1].name, "block 2");
  EXPECT_FALSE(start_collides(cell));
  // On the table top, 10, 15 or 20 mm up depending on the face it rests on.
  for (const auto& p : cell.parts) {
    const double lift = p.pose.translation().z() - 0.75;
    EXPECT_TRUE(std::abs(lift - 0.01) < 1e-3 || std::abs(lift - 0.015) < 1e-3 || std::abs(lift - 0.02) < 1e-3) << lift;
  }
  // A missing file and a part too wide for the gripper are named as such; the cell is unchanged.
  const Cell before = cell;
  try {
    add_part_from_mesh(cell, dir.file("none.stl"), 0.001, options);
    ADD_FAILURE() << "a missing mesh was added";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), dir.file("none.stl"));
  }
  test::write_box_stl(dir.path() / "wide.stl", 300, 300, 300);
  try {
    add_part_from_mesh(cell, dir.file("wide.stl"), 0.001, options);
    ADD_FAILURE() << "a 300 mm cube was added";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), dir.file("wide.stl"));
    EXPECT_EQ(e.field(), "handles");
    EXPECT_NE(e.reason().find("too wide"), std::string::npos) << e.what();
  }
  EXPECT_EQ(cell.parts.size(), before.parts.size());
}

TEST(CellEdits, TheDemonstrationFollowsTheParts) {
  test::TempFolder dir("demoplan_cell_edits");
  test::write_box_stl(dir.path() / "a.stl", 40, 30, 20);
  test::write_box_stl(dir.path() / "b.stl", 50, 30, 20);
  Cell cell = starter_cell(dir.file("cell.json"), "ur5", DEMOPLAN_DATA_DIR);
  add_part_from_mesh(cell, dir.file("a.stl"), 0.001, {.data_dir = DEMOPLAN_DATA_DIR});
  add_part_from_mesh(cell, dir.file("b.stl"), 0.001, {.data_dir = DEMOPLAN_DATA_DIR});
  const Scene two = build_cell_scene(cell, {.data_dir = DEMOPLAN_DATA_DIR});
  const SceneState start = cell_start_state(cell, two);
  Demonstration demo;
  demo.object_ids = {"a", "b"};
  Pose moved = start.objects[1];
  moved.translation().y() += 0.1;
  demo.events.push_back({10, 1, EventType::Grasp, 1.0, start.objects, {}});
  demo.events.push_back({40, 1, EventType::Release, 1.0, {start.objects[0], moved}, {}});
  demo.doubts.push_back({0, 0, 5, "a doubt on a"});
  demo.doubts.push_back({1, 20, 30, "a doubt on b"});

  // Part a removed: b's events and poses follow it to index 0; a's doubt goes with a.
  Cell without_a = cell;
  without_a.parts.erase(without_a.parts.begin());
  const Scene one = build_cell_scene(without_a, {.data_dir = DEMOPLAN_DATA_DIR});
  const Demonstration d1 = demonstration_for_parts(demo, one, cell_start_state(without_a, one));
  EXPECT_EQ(d1.object_ids, std::vector<std::string>{"b"});
  ASSERT_EQ(d1.events.size(), 2u);
  EXPECT_EQ(d1.events[1].object, 0);
  ASSERT_EQ(d1.events[1].poses.size(), 1u);
  EXPECT_TRUE(d1.events[1].poses[0].isApprox(moved));
  ASSERT_EQ(d1.doubts.size(), 1u);
  EXPECT_EQ(d1.doubts[0].object, 0);

  // Part b removed while it has events: refused, naming it.
  Cell without_b = cell;
  without_b.parts.pop_back();
  const Scene other = build_cell_scene(without_b, {.data_dir = DEMOPLAN_DATA_DIR});
  try {
    demonstration_for_parts(demo, other, cell_start_state(without_b, other));
    ADD_FAILURE() << "a part with events was dropped";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), "b");
    EXPECT_NE(std::string(e.what()).find("delete its events first"), std::string::npos) << e.what();
  }

  // A new part rests where the cell puts it at every event.
  test::write_box_stl(dir.path() / "c.stl", 40, 40, 20);
  Cell with_c = cell;
  add_part_from_mesh(with_c, dir.file("c.stl"), 0.001, {.data_dir = DEMOPLAN_DATA_DIR});
  const Scene three = build_cell_scene(with_c, {.data_dir = DEMOPLAN_DATA_DIR});
  const SceneState start3 = cell_start_state(with_c, three);
  const Demonstration d3 = demonstration_for_parts(demo, three, start3);
  EXPECT_EQ(d3.object_ids, (std::vector<std::string>{"a", "b", "c"}));
  for (const auto& e : d3.events) {
    ASSERT_EQ(e.poses.size(), 3u);
    EXPECT_TRUE(e.poses[2].isApprox(start3.objects[2]));
  }
  EXPECT_TRUE(d3.events[1].poses[1].isApprox(moved));
  EXPECT_TRUE(validate(d3).empty());
}

}  // namespace
}  // namespace demoplan

namespace demoplan {
namespace {

// The editor's cache of what parts derive from their meshes gives what a fresh build gives, and
// a change it depends on (the scale) is not served from it.
TEST(CellPartCache, ServesWhatAFreshBuildGives) {
  const std::string file = std::string(DEMOPLAN_DATA_DIR) + "/../cells/ur5_workbench.json";
  Cell cell = load_cell(file);
  CellPartCache cache;
  const CellSceneOptions cached{.data_dir = DEMOPLAN_DATA_DIR, .part_cache = &cache};
  const Scene fresh = build_cell_scene(cell, {.data_dir = DEMOPLAN_DATA_DIR});
  build_cell_scene(cell, cached);
  cell.parts[0].pose.translation().x() += 0.1;  // a move: served from the cache
  const Scene again = build_cell_scene(cell, cached);
  for (size_t k = 0; k < fresh.objects.size(); ++k) {
    ASSERT_EQ(again.objects[k].srdf.handles.size(), fresh.objects[k].srdf.handles.size());
    for (size_t h = 0; h < fresh.objects[k].srdf.handles.size(); ++h)
      EXPECT_TRUE(again.objects[k].srdf.handles[h].pose.isApprox(fresh.objects[k].srdf.handles[h].pose));
    EXPECT_EQ(again.objects[k].srdf.contacts[0].polygons.size(), fresh.objects[k].srdf.contacts[0].polygons.size());
  }
  cell.parts[0].scale *= 1.5;  // a larger part: placements and handles derived anew
  const Scene larger = build_cell_scene(cell, cached);
  const Scene larger_fresh = build_cell_scene(cell, {.data_dir = DEMOPLAN_DATA_DIR});
  ASSERT_EQ(larger.objects[0].srdf.handles.size(), larger_fresh.objects[0].srdf.handles.size());
  EXPECT_TRUE(larger.objects[0].srdf.handles[0].pose.isApprox(larger_fresh.objects[0].srdf.handles[0].pose));
  EXPECT_FALSE(larger.objects[0].srdf.handles[0].pose.isApprox(fresh.objects[0].srdf.handles[0].pose));
}

}  // namespace
}  // namespace demoplan

namespace demoplan {
namespace {

// The bundled UR5 laid out as ROS packages would be (my_arm_description/urdf/arm.urdf, its meshes
// as package://my_arm_description/meshes/..., its hand's as package://franka_description/...)
// under `root`; returns the URDF's path.
std::string write_ros_package_robot(const std::filesystem::path& root) {
  namespace fs = std::filesystem;
  const fs::path source = fs::path(DEMOPLAN_DATA_DIR) / "robots/ur5";
  const fs::path package = root / "src/my_arm_description";
  fs::create_directories(package / "urdf");
  fs::copy(source / "meshes", package / "meshes", fs::copy_options::recursive);
  std::ifstream in(source / "ur5.urdf");
  std::stringstream text;
  text << in.rdbuf();
  std::string urdf = text.str();
  // Its hand is the Panda's, from a second package.
  fs::create_directories(root / "src/franka_description");
  fs::copy(source / "../franka_panda/meshes", root / "src/franka_description/meshes", fs::copy_options::recursive);
  for (const auto& [from, to] : {std::pair<std::string, std::string>{"filename=\"meshes/", "filename=\"package://my_arm_description/meshes/"},
                                 {"filename=\"../franka_panda/meshes/", "filename=\"package://franka_description/meshes/"}})
    for (size_t at = urdf.find(from); at != std::string::npos; at = urdf.find(from, at + to.size()))
      urdf.replace(at, from.size(), to);
  std::ofstream(package / "urdf/arm.urdf") << urdf;
  fs::copy_file(source / "ur5.srdf", package / "urdf/arm.srdf");
  return (package / "urdf/arm.urdf").string();
}

TEST(CellEdits, TheRobotIsReplacedByABundledOneOrOneFromFiles) {
  test::TempFolder dir("demoplan_cell_edits");
  Cell cell = starter_cell(dir.file("cell.json"), "ur5", DEMOPLAN_DATA_DIR);
  const Pose base = cell.robot.base;
  const int ur5_joints = build_cell_scene(cell, {.data_dir = DEMOPLAN_DATA_DIR}).robot.model.nq;

  replace_robot(cell, "panda", "", "", DEMOPLAN_DATA_DIR);
  EXPECT_EQ(cell.robot.bundled, "panda");
  EXPECT_FALSE(cell.robot.mobile);
  EXPECT_TRUE(cell.robot.base.isApprox(base));
  EXPECT_EQ(build_cell_scene(cell, {.data_dir = DEMOPLAN_DATA_DIR}).robot.name, "panda");
  replace_robot(cell, "kmr_iiwa", "", "", DEMOPLAN_DATA_DIR);
  EXPECT_TRUE(cell.robot.mobile);
  EXPECT_EQ(cell.robot.base.translation().z(), 0.0);  // on the floor, not on the pedestal
  EXPECT_THROW(replace_robot(cell, "no_such_robot", "", "", DEMOPLAN_DATA_DIR), InputError);

  // A robot from disk whose meshes are package:// URIs: the folder holding the package is found
  // two levels above the URDF and the robot loads from it.
  const std::string urdf = write_ros_package_robot(dir.path() / "ws");
  std::vector<std::string> packages = urdf_package_names(urdf);
  std::sort(packages.begin(), packages.end());
  EXPECT_EQ(packages, (std::vector<std::string>{"franka_description", "my_arm_description"}));
  const std::string srdf = (std::filesystem::path(urdf).parent_path() / "arm.srdf").string();
  replace_robot(cell, "", urdf, srdf, DEMOPLAN_DATA_DIR);
  EXPECT_TRUE(cell.robot.bundled.empty());
  EXPECT_FALSE(cell.robot.mobile);
  ASSERT_EQ(cell.package_paths.size(), 1u);
  EXPECT_EQ(std::filesystem::path(cell.package_paths[0]), (dir.path() / "ws/src").lexically_normal());
  const Scene scene = build_cell_scene(cell, {.data_dir = DEMOPLAN_DATA_DIR});
  EXPECT_EQ(scene.robot.model.nq, ur5_joints);
  EXPECT_GE(scene.robot.gripper_link, 0);
  // Saved and loaded, the cell keeps the files and the package folder.
  save_cell(cell.file, cell);
  const Cell loaded = load_cell(cell.file);
  EXPECT_EQ(loaded.robot.urdf, cell.robot.urdf);
  EXPECT_EQ(loaded.package_paths, cell.package_paths);

  // Without the package folder the load names the mesh it cannot find.
  Cell lost = cell;
  lost.package_paths.clear();
  try {
    build_cell_scene(lost, {.data_dir = DEMOPLAN_DATA_DIR});
    ADD_FAILURE() << "a robot whose meshes cannot be found was loaded";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("package://my_arm_description/meshes"), std::string::npos) << e.what();
  }
  EXPECT_THROW(replace_robot(cell, "", dir.file("missing.urdf"), srdf, DEMOPLAN_DATA_DIR), InputError);
}

}  // namespace
}  // namespace demoplan

namespace demoplan {
namespace {

// A robot from disk made mobile: refused for an arm without planar base joints (the cell as it
// was), accepted for the KMR's URDF (off its pedestal, onto the floor), and made fixed again
// (a pedestal put back under it); a bundled robot's mobility is its data's.
TEST(CellEdits, ARobotFromDiskIsMadeMobileOnlyWithPlanarBaseJoints) {
  test::TempFolder dir("demoplan_cell_edits");
  const CellSceneOptions options{.data_dir = DEMOPLAN_DATA_DIR};
  Cell cell = starter_cell(dir.file("cell.json"), "ur5", DEMOPLAN_DATA_DIR);
  EXPECT_THROW(set_robot_mobile(cell, build_cell_scene(cell, options), true), InputError);  // bundled

  const std::string robots = std::string(DEMOPLAN_DATA_DIR) + "/robots/";
  replace_robot(cell, "", robots + "ur5/ur5.urdf", robots + "ur5/ur5.srdf", DEMOPLAN_DATA_DIR);
  const Cell arm = cell;
  try {
    set_robot_mobile(cell, build_cell_scene(cell, options), true);
    ADD_FAILURE() << "the UR5 was made mobile";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), cell.file);
    EXPECT_EQ(e.field(), "robot.mobile");
    EXPECT_NE(e.reason().find("ur5.urdf has no planar base joints"), std::string::npos) << e.what();
  }
  EXPECT_FALSE(cell.robot.mobile);
  EXPECT_EQ(cell.furniture.size(), arm.furniture.size());
  // A cell file that says so by hand is refused the same way when it is loaded.
  Cell by_hand = cell;
  by_hand.robot.mobile = true;
  try {
    build_cell_scene(by_hand, options);
    ADD_FAILURE() << "a cell with a mobile UR5 loaded";
  } catch (const InputError& e) {
    EXPECT_EQ(e.field(), "robot.mobile");
  }

  const std::string kmr = robots + "kuka_kmr_iiwa/kuka_kmr_iiwa";
  replace_robot(cell, "", kmr + ".urdf", kmr + ".srdf", DEMOPLAN_DATA_DIR);
  ASSERT_EQ(cell.furniture.size(), 2u);  // the pedestal and the table
  set_robot_mobile(cell, build_cell_scene(cell, options), true);
  EXPECT_TRUE(cell.robot.mobile);
  EXPECT_EQ(cell.robot.base.translation().z(), 0.0);
  ASSERT_EQ(cell.furniture.size(), 1u);
  EXPECT_EQ(cell.furniture[0].name, "table");
  const Scene mobile = build_cell_scene(cell, options);
  EXPECT_FALSE(mobile.robot.fixed_base);
  save_cell(cell.file, cell);
  EXPECT_TRUE(load_cell(cell.file).robot.mobile);

  set_robot_mobile(cell, mobile, false);
  EXPECT_FALSE(cell.robot.mobile);
  EXPECT_DOUBLE_EQ(cell.robot.base.translation().z(), 0.75);
  ASSERT_EQ(cell.furniture.size(), 2u);
  EXPECT_EQ(cell.furniture[1].name, "pedestal");
  EXPECT_FALSE(cell.furniture[1].auto_supports);
  EXPECT_EQ(robot_pedestal(build_cell_scene(cell, options)), 1);
}

}  // namespace
}  // namespace demoplan
