// Where to put the robot (issue 18): the region and its candidates, the support box of a base
// the benchmark does not publish, a base that does not fit, the search itself on shelf_1, and
// shards merged into the ranking of one run.
#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include "core/cell/cell.h"
#include "core/cell/cell_picks.h"
#include "core/cell/cell_scene.h"
#include "core/demo/benchmark_demonstration.h"
#include "core/demo/benchmark_scene.h"
#include "core/error.h"
#include "core/io/json_file.h"
#include "core/io/shards.h"
#include "core/placement/base_clearance.h"
#include "core/geometry/polygon_2d.h"
#include "core/placement/furniture_footprints.h"
#include "core/placement/placement_result.h"
#include "core/placement/placement_search.h"
#include "core/project/benchmark_instance.h"
#include "core/project/placement_problem.h"
#include "tests/support/temp_folder.h"

using namespace demoplan;

namespace {

const std::string kData = DEMOPLAN_DATA_DIR;

// The field an InputError names, or "" when `f` throws none.
template <typename F>
std::string error_field(F&& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.field() + ": " + e.reason();
  }
  return "";
}

PlacementCandidate candidate(int index, double success, std::optional<double> cycle) {
  PlacementCandidate c;
  c.index = index;
  c.base = {0.1 * index, 0.2, 1.0, 0.3};
  c.screened = true;
  c.feasible = success > 0 || cycle.has_value();
  c.reason = c.feasible ? "" : "pick 1 (YCBV_05) cannot be done";
  for (int k = 0; k < 4; ++k) {
    PlacementRun run;
    run.seed = static_cast<std::uint64_t>(k + 1);
    run.valid = k < std::lround(success * 4);
    run.planning_time_s = 0.1 * (k + 1);
    if (run.valid) run.cycle_time_s = cycle.value_or(10) + k, run.path_length = 3.0;
    if (c.feasible) c.runs.push_back(run);
  }
  return c;
}

}  // namespace

TEST(BasePlacement, TheRegionIsReadAndEveryBadRangeNamed) {
  const PlacementRegion r = parse_placement_region("-0.2:1,0:0.5,-3.1416:3.1416");
  EXPECT_DOUBLE_EQ(r.x.low, -0.2);
  EXPECT_DOUBLE_EQ(r.y.high, 0.5);
  EXPECT_DOUBLE_EQ(r.yaw.low, -3.1416);
  EXPECT_FALSE(r.z.has_value());
  EXPECT_EQ(parse_placement_region(to_string(r)).x.low, r.x.low);  // written as it reads back
  EXPECT_DOUBLE_EQ(parse_placement_region("0:1,0:1,0:0,0.8:1.1").z->high, 1.1);
  EXPECT_NE(error_field([] { parse_placement_region("1:0,0:1,0:1"); }).find("x range '1:0' is inverted"), std::string::npos);
  EXPECT_NE(error_field([] { parse_placement_region("0:1,0.5:0.5,0:1"); }).find("y range '0.5:0.5' is empty"), std::string::npos);
  EXPECT_NE(error_field([] { parse_placement_region("0:1,0:1,a:1"); }).find("'a' is not a number"), std::string::npos);
  EXPECT_NE(error_field([] { parse_placement_region("0:1,0:1"); }).find("--region"), std::string::npos);
  EXPECT_NE(error_field([] { parse_placement_region("0:1,0:1,0:1,2:1"); }).find("z range"), std::string::npos);
}

TEST(BasePlacement, CandidatesCoverTheRegionEvenlyAndShardsPartitionThem) {
  const PlacementRegion r = parse_placement_region("-0.6:0.6,-0.6:0.6,-3.14159:3.14159");
  const std::vector<BasePose> c = candidate_base_poses(r, 200, 1.05);
  ASSERT_EQ(c.size(), 200u);
  int quadrant[4] = {0, 0, 0, 0}, half_yaw = 0;
  for (const BasePose& p : c) {
    EXPECT_TRUE(p.x >= -0.6 && p.x <= 0.6 && p.y >= -0.6 && p.y <= 0.6) << p.x << " " << p.y;
    EXPECT_DOUBLE_EQ(p.z, 1.05);
    quadrant[(p.x > 0) + 2 * (p.y > 0)]++;
    half_yaw += p.yaw > 0;
  }
  for (int q : quadrant) EXPECT_NEAR(q, 50, 4);  // a low-discrepancy sequence, not random clumps
  EXPECT_NEAR(half_yaw, 100, 4);
  EXPECT_EQ(candidate_base_poses(r, 200, 1.05)[117].yaw, c[117].yaw);  // the same every time
  std::set<int> all;
  for (int s = 1; s <= 4; ++s)
    for (int i : shard_indices(200, s, 4)) EXPECT_TRUE(all.insert(i).second) << i << " in two shards";
  EXPECT_EQ(all.size(), 200u);
  EXPECT_NE(error_field([] { shard_indices(200, 5, 4); }).find("--shard"), std::string::npos);
  EXPECT_NE(error_field([] { shard_indices(200, 0, 4); }).find("--shard"), std::string::npos);
}

TEST(BasePlacement, TheSupportBoxOfEveryPublishedPoseIsMadeAgain) {
  int boxes = 0;
  for (const std::string& name : list_benchmark_tasks(kData)) {
    const BenchmarkTask task = load_benchmark_task(kData, name);
    for (const auto& [robot, file] : task.robot_pose_files) {
      const BenchmarkRobot info = load_benchmark_robot(kData, robot);
      if (!info.fixed_base) continue;
      const Json json = read_json_file(file);
      for (int id : benchmark_pose_ids(task, robot)) {
        SCOPED_TRACE(name + " " + robot + " " + std::to_string(id));
        const Scene scene = build_benchmark_scene(task, robot, id);
        const JsonField published = JsonField(json, file)["support_box"][std::to_string(id)];
        const SupportBox box = support_box_at(scene, info, scene.robot.base);
        EXPECT_LT((box.size - Eigen::Vector3d(published["size"].vector())).norm(), 1e-9);
        EXPECT_LT((box.pose.matrix() - published["pose"].pose().matrix()).norm(), 1e-9);
        ++boxes;
      }
    }
  }
  EXPECT_GE(boxes, 40);
}

TEST(BasePlacement, ABaseInsideTheShelfDoesNotFitAndAMobileRobotIsNotPlaced) {
  const BenchmarkTask task = load_benchmark_task(kData, "shelf_1");
  const BenchmarkRobot panda = load_benchmark_robot(kData, "panda");
  Scene scene = build_benchmark_scene(task, "panda", 0);
  EXPECT_EQ(base_clearance(scene), "");  // the published pose, on its box
  move_benchmark_robot(scene, panda, BasePose{0.8875, 0.7222, 1.117, 1.64}.pose());
  EXPECT_NE(base_clearance(scene).find("inside shelf_1_1_shelf"), std::string::npos) << base_clearance(scene);
  int boxes = 0;
  for (const auto& f : scene.furniture) boxes += f.kind == kSupportBoxKind;
  EXPECT_EQ(boxes, 1);  // moved, not added
  Scene kmr = build_benchmark_scene(task, "kmr_iiwa", 0);
  EXPECT_NE(error_field([&] { move_benchmark_robot(kmr, load_benchmark_robot(kData, "kmr_iiwa"), Pose::Identity()); })
                .find("mobile"),
            std::string::npos);
}

TEST(BasePlacement, TheSearchPlansWhereTheRobotFitsAndSaysWhyElsewhere) {
  const BenchmarkTask task = load_benchmark_task(kData, "shelf_1");
  const BenchmarkRobot panda = load_benchmark_robot(kData, "panda");
  const auto scene = std::make_shared<const Scene>(build_benchmark_scene(task, "panda", 0));
  const ProblemAtBase at = [&](const Pose& base) {
    Scene moved = *scene;
    move_benchmark_robot(moved, panda, base);
    return make_benchmark_instance(task, std::make_shared<const Scene>(std::move(moved)), PoseSource::Subgoals).problem;
  };
  const Pose published = scene->robot.base;
  const double yaw = std::atan2(published(1, 0), published(0, 0));
  const std::vector<BasePose> candidates{
      {published.translation().x(), published.translation().y(), published.translation().z(), yaw},
      {0.8875, 0.7222, 1.117, 1.64},  // in the shelf
      {2.5, 2.5, 1.117, 0.0}};        // far from every part
  PlacementSettings settings;
  settings.seeds = {1, 2};
  settings.planner.planner.time_limit = 30;
  std::vector<size_t> reported;
  std::vector<PlacementCandidate> out = run_placement_search(
      at, candidates, {0, 1, 2}, settings, 2, [&](const PlacementCandidate&, size_t done, size_t) { reported.push_back(done); });
  ASSERT_EQ(out.size(), 3u);
  EXPECT_EQ(reported, (std::vector<size_t>{1, 2, 3}));
  EXPECT_TRUE(out[0].feasible) << out[0].reason;
  EXPECT_DOUBLE_EQ(out[0].success_rate(), 1.0);
  ASSERT_TRUE(out[0].cycle_time_s().has_value());
  EXPECT_GT(*out[0].cycle_time_s(), 2.0);  // two picks cannot be done in less
  EXPECT_LT(*out[0].cycle_time_s(), 60.0);
  EXPECT_FALSE(out[1].feasible);
  EXPECT_NE(out[1].reason.find("inside"), std::string::npos) << out[1].reason;
  EXPECT_TRUE(out[1].runs.empty());  // rejected by the screen, never planned
  EXPECT_FALSE(out[2].feasible);
  EXPECT_NE(out[2].reason.find("out of reach"), std::string::npos) << out[2].reason;
  rank_candidates(out);
  EXPECT_EQ(out.front().index, 0);
}

TEST(BasePlacement, ShardsMergeIntoTheRankingOfOneRunAndForeignShardsAreRefused) {
  const test::TempFolder dir("placement-merge");
  std::vector<PlacementCandidate> all{candidate(0, 0, std::nullopt), candidate(1, 1.0, 12.0), candidate(2, 0.5, 9.0),
                                      candidate(3, 1.0, 10.5), candidate(4, 0.0, std::nullopt),
                                      candidate(5, 1.0, 10.5)};
  PlacementResult one;
  one.arguments = {{"task", "shelf_1"}, {"region", "0:1,0:1,0:1"}, {"samples", 6}};
  one.candidate_count = 6;
  one.candidates = all;
  rank_candidates(one.candidates);
  std::vector<int> expected;
  for (const auto& c : one.candidates) expected.push_back(c.index);
  // Success first, then cycle time, then the index: 3 and 5 tie on both.
  EXPECT_EQ(expected, (std::vector<int>{3, 5, 1, 2, 0, 4}));

  std::vector<std::string> files;
  for (int s = 1; s <= 3; ++s) {
    PlacementResult part = one;
    part.shard = s, part.shards = 3;
    part.candidates.clear();
    for (int i : shard_indices(6, s, 3)) part.candidates.push_back(all[static_cast<size_t>(i)]);
    files.push_back(dir.path() / ("place-" + std::to_string(s) + ".json"));
    save_placement_result(files.back(), part);
  }
  const PlacementResult merged = merge_placement_results({files[2], files[0], files[1]});
  EXPECT_TRUE(merged.complete());
  std::vector<int> got;
  for (const auto& c : merged.candidates) got.push_back(c.index);
  EXPECT_EQ(got, expected);
  EXPECT_EQ(placement_result_json(merged)["candidates"], placement_result_json(one)["candidates"]);  // bit for bit

  EXPECT_NE(error_field([&] { merge_placement_results({files[0], files[1]}); }).find("shard 3 of 3 is missing"),
            std::string::npos);
  EXPECT_NE(error_field([&] { merge_placement_results({files[0], files[0], files[1], files[2]}); }).find("also in"),
            std::string::npos);
  PlacementResult other = load_placement_result(files[1]);
  other.arguments["samples"] = 7;
  const std::string foreign = dir.path() / "other.json";
  save_placement_result(foreign, other);
  EXPECT_NE(error_field([&] { merge_placement_results({files[0], foreign, files[2]}); }).find("arguments"),
            std::string::npos);
}

TEST(BasePlacement, ARegionWhereNothingFitsSaysWhy) {
  PlacementResult r;
  r.candidate_count = 3;
  for (int i = 0; i < 3; ++i) r.candidates.push_back(candidate(i, 0, std::nullopt));
  EXPECT_NE(r.message().find("no base pose of the 3 in the region can do every pick"), std::string::npos) << r.message();
  EXPECT_NE(r.message().find("pick 1 (YCBV_05) cannot be done"), std::string::npos);
  r.candidates[1] = candidate(1, 1.0, 8.0);
  EXPECT_EQ(r.message(), "");
}

TEST(BasePlacement, ABaseThatDoesNotFitRanksLastEvenWhenPlannedValid) {
  // --plan-rejected plans rejected candidates too; the planner never checks the base against the
  // furniture, so a base inside the shelf can get valid plans. It must not be recommended.
  PlacementCandidate inside = candidate(0, 1.0, 5.0);
  inside.feasible = false;
  inside.reason = "the robot's panda_link0 is inside shelf_1_1_shelf/top_desk";
  std::vector<PlacementCandidate> all{inside, candidate(1, 0.5, 12.0)};
  rank_candidates(all);
  EXPECT_EQ(all.front().index, 1);
  EXPECT_FALSE(all.back().usable());
  PlacementResult r;
  r.candidate_count = 2;
  r.candidates = all;
  EXPECT_EQ(placement_result_json(r)["ranking"], nlohmann::json::array({1}));
}

TEST(BasePlacement, ACellsRobotTakesItsPedestalAlongAndNeverFloats) {
  // ur5_workbench: the UR5 on a 0.75 m pedestal beside the workbench the parts rest on.
  const Cell cell = load_cell(kData + "/../cells/ur5_workbench.json");
  const auto scene = std::make_shared<const Scene>(build_cell_scene(cell, {.data_dir = kData}));
  const int pedestal = robot_pedestal(*scene);
  ASSERT_GE(pedestal, 0);
  EXPECT_EQ(scene->furniture[static_cast<size_t>(pedestal)].name, "pedestal");
  EXPECT_EQ(base_clearance(*scene), "");
  const SceneState start = cell_start_state(cell, *scene);
  const RandomPickReport picks = random_picks(*scene, start, 1, 1);
  ASSERT_EQ(picks.picks.size(), 1u) << picks.failure;
  const auto demo = std::make_shared<const Demonstration>(demonstration_from_picks(*scene, start, picks.picks, "one pick"));
  const BasePose there{-0.1, 0.2, 0.75, 0.7};  // back from the workbench, turned
  const PlanningProblem problem = problem_at_base(scene, demo, std::nullopt)(there.pose());
  const Scene& moved = *problem.scene;
  EXPECT_EQ(base_clearance(moved), "");
  EXPECT_NEAR((moved.furniture[static_cast<size_t>(pedestal)].link_poses[0].translation() -
               Eigen::Vector3d(-0.1, 0.2, 0.375)).norm(), 0.0, 1e-9);
  EXPECT_NEAR((moved.robot.base.translation() - Eigen::Vector3d(-0.1, 0.2, 0.75)).norm(), 0.0, 1e-12);
  EXPECT_EQ(moved.furniture[1].link_poses[0].translation(), scene->furniture[1].link_poses[0].translation());  // the workbench stays
  // Without its pedestal the robot would hang in the air; inside the workbench it does not fit.
  Scene floating = *scene;
  floating.robot.base = there.pose();
  EXPECT_NE(base_clearance(floating).find("stands on nothing"), std::string::npos) << base_clearance(floating);
  const PlanningProblem into = problem_at_base(scene, demo, std::nullopt)(BasePose{0.55, 0.0, 0.75, 0.0}.pose());
  EXPECT_NE(base_clearance(*into.scene).find("inside workbench"), std::string::npos) << base_clearance(*into.scene);
}

TEST(BasePlacement, TheFurnitureIsOutlinedFromAboveWithoutThePedestal) {
  const BenchmarkTask task = load_benchmark_task(kData, "shelf_1");
  const std::vector<Footprint> shelf = furniture_footprints(build_benchmark_scene(task, "panda", 0));
  ASSERT_EQ(shelf.size(), 2u);  // the table and the shelf; the support box moves with the robot
  for (const Footprint& f : shelf) {
    ASSERT_GE(f.outline.size(), 4u) << f.name;
    double area = 0;  // counter-clockwise: positive
    for (size_t i = 0; i < f.outline.size(); ++i)
      area += cross2(f.outline[i], f.outline[(i + 1) % f.outline.size()]) / 2;
    EXPECT_GT(area, 0.1) << f.name;  // m^2: a table and a shelf, not a sliver
  }
  const Cell cell = load_cell(kData + "/../cells/ur5_workbench.json");
  const std::vector<Footprint> bench = furniture_footprints(build_cell_scene(cell, {.data_dir = kData}));
  ASSERT_EQ(bench.size(), 2u);  // the workbench and the fixture, not the pedestal
  EXPECT_EQ(bench[0].name, "workbench");
  double x_max = -1;
  for (const auto& p : bench[0].outline) x_max = std::max(x_max, p.x());
  EXPECT_NEAR(x_max, 1.05, 1e-9);  // 0.8 m wide at x 0.65
}
