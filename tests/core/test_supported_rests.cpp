// A demonstration whose part is released where no support holds it (a part put into a shelf
// where the camera never saw it land: its last pose floats) is refused before planning, naming
// the event, its frame and the part and how far it floats; one a few millimetres off its support
// is settled onto it, planned, and its path validates.
#include <gtest/gtest.h>

#include "core/cell/cell_scene.h"
#include "core/demo/settle_demonstration.h"
#include "core/demo/supported_rests.h"
#include "core/error.h"
#include "core/planning/plan_job.h"
#include "core/project/benchmark_instance.h"
#include "tests/support/box_stl.h"
#include "tests/support/temp_folder.h"

namespace demoplan {
namespace {

constexpr double kTop = 0.75;           // the table top
constexpr double kHalfHeight = 0.04;    // the 40 x 50 x 80 mm block stands on its 40 x 50 face

// A Panda on a table, one block of an STL the test writes, standing on the table.
Cell table_cell(const test::TempFolder& dir) {
  test::write_box_stl(dir.path() / "block.stl", 40, 50, 80);
  Cell c;
  c.file = dir.file("cell.json");
  c.name = "test cell";
  c.robot.bundled = "panda";
  c.robot.base.translation() = Eigen::Vector3d(0, 0, kTop);
  CellFurniture table;
  table.name = "table";
  table.box = {1.2, 1.0, kTop};
  table.pose.translation() = Eigen::Vector3d(0.4, 0, kTop / 2);
  c.furniture.push_back(table);
  CellPart block;
  block.name = "block";
  block.mesh = dir.file("block.stl");
  block.scale = 0.001;
  block.pose.translation() = Eigen::Vector3d(0.45, -0.2, kTop + kHalfHeight + 0.001);
  c.parts.push_back(block);
  return c;
}

// Grasped where it rests (1 mm up), released 35 cm further, turned a quarter, its face `lift` above the table.
Demonstration one_pick(const Scene& scene, double lift) {
  Demonstration d;
  d.task = "test cell";
  d.object_ids = {scene.objects[0].id};
  Pose at = Pose::Identity(), to = Pose::Identity();
  at.translation() = Eigen::Vector3d(0.45, -0.2, kTop + kHalfHeight + 0.001);
  to.linear() = Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  to.translation() = Eigen::Vector3d(0.45, 0.15, kTop + kHalfHeight + lift);
  d.events.push_back({20, 0, EventType::Grasp, 1.0, {at}, {}});
  d.events.push_back({60, 0, EventType::Release, 1.0, {to}, {}});
  return d;
}

TEST(SupportedRests, AReleaseFiveCentimetresUpIsRefusedNamingTheEvent) {
  test::TempFolder dir("demoplan_supported_rests");
  const Scene scene = build_cell_scene(table_cell(dir), {.data_dir = DEMOPLAN_DATA_DIR});
  const Demonstration floating = one_pick(scene, 0.05);
  const auto rests = unsupported_rests(scene, floating);
  ASSERT_EQ(rests.size(), 1u);
  EXPECT_EQ(rests[0].event, 1);
  EXPECT_EQ(rests[0].frame, 60);
  EXPECT_EQ(rests[0].object, 0);
  try {
    settle_for_planning(scene, floating, "demo.json");
    ADD_FAILURE() << "a part floating 5 cm above the table was planned";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), "demo.json");
    EXPECT_EQ(e.field(), "events[1] (frame 60)");
    EXPECT_EQ(e.reason().rfind("block rests on no support: 50 mm above the nearest (table/", 0), 0u) << e.what();
    EXPECT_NE(e.reason().find("; move it onto a support"), std::string::npos) << e.what();
  }
  // Pushed into the table and put beside it, it is named as such too.
  Demonstration sunk = one_pick(scene, -0.03);
  EXPECT_NE(unsupported_rests(scene, settle_on_supports(scene, sunk)).at(0).message.find("30 mm into the nearest (table/"),
            std::string::npos);
  Demonstration beside = one_pick(scene, 0.0);
  beside.events[1].poses[0].translation().x() = 1.5;
  EXPECT_NE(unsupported_rests(scene, beside).at(0).message.find("over none (the nearest is table/"), std::string::npos)
      << unsupported_rests(scene, beside).at(0).message;
}

TEST(SupportedRests, AReleaseTwoMillimetresUpIsSettledPlannedAndValidated) {
  test::TempFolder dir("demoplan_supported_rests");
  const auto scene = std::make_shared<const Scene>(build_cell_scene(table_cell(dir), {.data_dir = DEMOPLAN_DATA_DIR}));
  // 2 mm above where it would rest (1 mm up): its face 3 mm up, out of the placement test's 2 mm slab.
  const Demonstration off = one_pick(*scene, 0.003);
  ASSERT_EQ(unsupported_rests(*scene, off).size(), 1u);
  const Demonstration settled = settle_for_planning(*scene, off, "demo.json");
  EXPECT_TRUE(unsupported_rests(*scene, settled).empty());
  EXPECT_NEAR(settled.events[1].poses[0].translation().z(), kTop + kHalfHeight + 0.001, 1e-6);

  const BenchmarkInstance instance = make_benchmark_instance(scene, settled);
  PlannerSettings settings;
  settings.planner.seed = 1;
  settings.planner.time_limit = 60;
  const PlanReport report = run_plan_job(instance.problem, settings);
  ASSERT_TRUE(report.solved()) << report.plan.message;
  EXPECT_TRUE(report.valid()) << report.validation.message;
}

// The one pick with the block released standing on a tray whose top is at `tray`, and the line
// of sight from `eye` to where it truly is.
struct TrayRelease {
  Demonstration demonstration;
  Pose truth;
  Eigen::Vector3d sight;
};
TrayRelease released_on_tray(const Scene& scene, double tray, const Eigen::Vector3d& eye) {
  TrayRelease r{one_pick(scene, 0.0), Pose::Identity(), Eigen::Vector3d::Zero()};
  r.demonstration.events[1].poses[0].translation().z() = tray + kHalfHeight + 0.001;
  r.truth = r.demonstration.events[1].poses[0];
  r.sight = (r.truth.translation() - eye).normalized();
  return r;
}

// A square of side 2 `half` around (x, y) at height z, counter-clockwise from above.
std::vector<Eigen::Vector3d> square(double x, double y, double half, double z) {
  return {{x - half, y - half, z}, {x + half, y - half, z}, {x + half, y + half, z}, {x - half, y + half, z}};
}

// A part set on a tray the demonstrator holds (no furniture under it) is measured from its image
// alone, its depth centimetres off: settled onto the tray's top given for that event, along its
// line of sight, it rests where it was put; a tray its line of sight misses holds nothing.
TEST(SupportedRests, APartOnATrayIsSettledOntoItsTopAlongItsLineOfSight) {
  test::TempFolder dir("demoplan_supported_rests");
  const Scene scene = build_cell_scene(table_cell(dir), {.data_dir = DEMOPLAN_DATA_DIR});
  const double tray = kTop + 0.3;  // held 30 cm above the table
  const Eigen::Vector3d eye(-1.0, 0.15, 2.0);
  auto [d, truth, sight] = released_on_tray(scene, tray, eye);
  Pose& released = d.events[1].poses[0];
  released.translation() -= 0.05 * sight;  // seen 5 cm nearer
  SettleOptions options;
  options.snap.viewpoint = eye;
  const EventSupports under(2, {square(0.45, 0.15, 0.15, tray)});
  const Demonstration settled = settle_on_supports(scene, d, options, under);
  EXPECT_LT((settled.events[1].poses[0].translation() - truth.translation()).norm(), 1e-3);
  EXPECT_LT((settled.events[0].poses[0].translation() - d.events[0].poses[0].translation()).norm(), 1e-3)
      << "the grasp's rest on the table is the table's";
  const EventSupports beside(2, {square(1.2, 0.15, 0.15, tray)});
  EXPECT_TRUE(settle_on_supports(scene, d, options, beside).events[1].poses[0].isApprox(released, 1e-12));
  EXPECT_TRUE(settle_on_supports(scene, d, options).events[1].poses[0].isApprox(released, 1e-12));
}

// A part on a thin tray lying on the table is within centimetres of both tops: seen with its
// bottom 5 mm under the tray's top (11 mm over the table's), it is settled onto the nearer top,
// the tray's, not pushed through the tray onto the table.
TEST(SupportedRests, APartOnATrayLyingOnTheTableIsSettledOntoTheNearerTop) {
  test::TempFolder dir("demoplan_supported_rests");
  const Scene scene = build_cell_scene(table_cell(dir), {.data_dir = DEMOPLAN_DATA_DIR});
  const double tray = kTop + 0.001 + 0.015;  // a 15 mm tray on the table
  const Eigen::Vector3d eye(-1.0, 0.15, 2.0);
  auto [d, truth, sight] = released_on_tray(scene, tray, eye);
  d.events[1].poses[0].translation() += 0.006 / -sight.z() * sight;  // seen farther along its line of sight: 6 mm lower
  SettleOptions options;
  options.snap.viewpoint = eye;
  const EventSupports on_table(2, {square(0.45, 0.15, 0.15, tray)});
  EXPECT_LT((settle_on_supports(scene, d, options, on_table).events[1].poses[0].translation() - truth.translation()).norm(), 1e-3);
  // Without the tray, the table holds it.
  EXPECT_NEAR(settle_on_supports(scene, d, options).events[1].poses[0].translation().z(), kTop + kHalfHeight + 0.001, 1e-6);
}

}  // namespace
}  // namespace demoplan
