// The guided planner on real benchmark scenes: solves, reproduces bit for bit, honours cancel,
// reports progress; the validator rejects paths broken on purpose.
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <random>
#include <thread>

#include "core/error.h"
#include "core/planning/guided_planner.h"
#include "core/planning/plan_job.h"
#include "core/planning/planner_registry.h"
#include "tests/core/planning_problem.h"
#include "tests/support/data_2024.h"

using namespace demoplan;

namespace {

BenchmarkProblem& shelf0() {
  static BenchmarkProblem p("shelf_0", "panda", 1);
  return p;
}

PlannerParams params(std::uint64_t seed, double time_limit = 30.0) {
  PlannerParams p;
  p.seed = seed;
  p.time_limit = time_limit;
  return p;
}

// A solved path of shelf_0 (one object) for the corruption tests.
const Path& solved_path() {
  static const Path path = [] {
    BenchmarkProblem& p = shelf0();
    PlanResult r = p.plan(params(1));
    EXPECT_TRUE(r.solved) << r.message;
    return r.path;
  }();
  return path;
}

size_t first_with_action(const Path& p, GripperAction a) {
  for (size_t k = 0; k < p.waypoints.size(); ++k)
    if (p.waypoints[k].action == a) return k;
  return p.waypoints.size();
}

}  // namespace

TEST(GuidedPlanner, SolvesAOneObjectShelfTaskWithAValidPath) {
  BenchmarkProblem& p = shelf0();
  const Path& path = solved_path();
  const ValidationReport v = validate_path(p.scene, p.vtask, path);
  EXPECT_TRUE(v.valid) << v.message;
  EXPECT_EQ(v.grasps, 1);
  EXPECT_GT(v.length.object_translation, 0.3);  // the object went from the table to the shelf
  // One grasp and one release, in that order, of the only object.
  const size_t g = first_with_action(path, GripperAction::Grasp), r = first_with_action(path, GripperAction::Release);
  ASSERT_LT(g, path.waypoints.size());
  ASSERT_LT(r, path.waypoints.size());
  EXPECT_LT(g, r);
}

TEST(GuidedPlanner, TheSameSeedGivesTheSamePathBitForBit) {
  BenchmarkProblem& p = shelf0();
  const PlanResult a = p.plan(params(7));
  const PlanResult b = p.plan(params(7));
  ASSERT_TRUE(a.solved && b.solved);
  EXPECT_EQ(a.iterations, b.iterations);
  ASSERT_EQ(a.path.waypoints.size(), b.path.waypoints.size());
  for (size_t k = 0; k < a.path.waypoints.size(); ++k) {
    EXPECT_TRUE((a.path.waypoints[k].q.array() == b.path.waypoints[k].q.array()).all()) << "waypoint " << k;
    EXPECT_EQ(a.path.waypoints[k].state, b.path.waypoints[k].state);
  }
  const PlanResult c = p.plan(params(8));
  ASSERT_TRUE(c.solved);
  EXPECT_FALSE(c.path.waypoints.size() == a.path.waypoints.size() &&
               (c.path.waypoints[1].q.array() == a.path.waypoints[1].q.array()).all());
}

// Cancel is honoured long before the time limit. How soon is a benchmark figure
// (bench/bench_cancel: at most 3.9 ms), not a unit test's: a loaded machine cannot time 100 ms.
TEST(GuidedPlanner, CancelStopsThePlannerLongBeforeItsTimeLimit) {
  // shelf_1 with Panda at pose 0 and YCBV_05's 2024 handles has no solution (the bottle cannot
  // be released on the table from this base pose): the planner would run to its time limit.
  BenchmarkProblem p("shelf_1", "panda", 0, demoplan::testdata::data_dir_with_2024_bottle(DEMOPLAN_DATA_DIR));
  std::atomic<bool> cancel{false};
  std::chrono::steady_clock::time_point cancelled_at;
  std::thread canceller([&] {
    std::this_thread::sleep_for(std::chrono::milliseconds(400));
    cancelled_at = std::chrono::steady_clock::now();
    cancel = true;
  });
  const PlanResult r = p.plan(params(1, 30.0), {}, &cancel);
  const auto returned = std::chrono::steady_clock::now();
  canceller.join();
  EXPECT_FALSE(r.solved);
  EXPECT_TRUE(r.cancelled);
  EXPECT_LT(std::chrono::duration<double>(returned - cancelled_at).count(), 5.0);  // limit: 30 s
  EXPECT_GT(r.iterations, 0);
}

// Progress comes while planning, every progress_period (0.05 s), not only at the end. The bounds
// leave room for a loaded machine: what matters is that the reports keep coming.
TEST(GuidedPlanner, ReportsProgressWhilePlanning) {
  BenchmarkProblem p("shelf_1", "panda", 0, demoplan::testdata::data_dir_with_2024_bottle(DEMOPLAN_DATA_DIR));
  PlannerParams pp = params(1, 1.0);
  std::vector<PlannerProgress> snapshots;
  size_t edges = 0;
  const PlanResult r = p.plan(pp, [&](const PlannerProgress& s) {
    snapshots.push_back(s);
    edges += s.new_edges.size();
  });
  ASSERT_GE(snapshots.size(), 5u);  // a 1 s search
  EXPECT_TRUE(snapshots.back().final);
  for (size_t k = 1; k + 1 < snapshots.size(); ++k) {
    EXPECT_GE(snapshots[k].elapsed_s - snapshots[k - 1].elapsed_s, pp.progress_period * 0.9);  // and not flooding
    EXPECT_LT(snapshots[k].elapsed_s - snapshots[k - 1].elapsed_s, 0.5);
  }
  EXPECT_EQ(snapshots.back().nodes, r.nodes);
  size_t per_state = 0;
  for (size_t n : snapshots.back().state_nodes) per_state += n;
  EXPECT_EQ(per_state, r.nodes);
  EXPECT_GT(edges, 0u);
  EXPECT_FALSE(r.unsampled_transitions.empty());  // the unreachable releases are named
}

// Edges checked far too coarsely (every 0.4 rad) cut through obstacles; the final check at the
// benchmark's sampling must catch those paths and planning must go on to a valid one.
TEST(GuidedPlanner, TheFinalCheckRejectsPathsThatPassThroughObstacles) {
  BenchmarkProblem p("shelf_1", "panda", 1);
  int invalid_unchecked = 0, rejected = 0;
  for (std::uint64_t seed = 1; seed <= 3; ++seed) {
    PlannerParams coarse = params(seed);
    coarse.resolution = 0.4;
    coarse.final_check = false;
    const PlanResult unchecked = p.plan(coarse);
    ASSERT_TRUE(unchecked.solved) << unchecked.message;
    if (!validate_path(p.scene, p.vtask, unchecked.path).valid) ++invalid_unchecked;

    coarse.final_check = true;
    const PlanResult checked = p.plan(coarse);
    ASSERT_TRUE(checked.solved) << checked.message;
    const ValidationReport v = validate_path(p.scene, p.vtask, checked.path);
    EXPECT_TRUE(v.valid) << "seed " << seed << ": " << v.message;
    rejected += checked.rejected_paths;
  }
  std::printf("coarse edges: %d of 3 paths invalid without the final check; %d rejected with it\n",
              invalid_unchecked, rejected);
  EXPECT_GT(invalid_unchecked, 0);  // without the check the coarse planner does return bad paths
  EXPECT_GT(rejected, 0);
}

// The validator catches paths broken on purpose, naming what and where.
class BrokenPath : public ::testing::Test {
protected:
  void expect_invalid(const Path& p, const std::string& words) {
    const ValidationReport v = validate_path(shelf0().scene, shelf0().vtask, p);
    EXPECT_FALSE(v.valid);
    EXPECT_NE(v.message.find(words), std::string::npos) << v.message;
    std::printf("rejected: %s\n", v.message.c_str());
  }
  // Moves waypoint w's arm to a (seeded random) configuration that hits the table or the
  // robot's support box.
  void put_into_table(Waypoint& w, std::uint64_t seed) const {
    const auto& model = shelf0().scene.robot.model;
    CollisionData data = shelf0().checker->make_data();
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(0, 1);
    CollisionPair hit;
    do {
      for (int i = 0; i < 7; ++i) w.q[i] = model.lower_limits()[i] + u(rng) * (model.upper_limits()[i] - model.lower_limits()[i]);
    } while (!shelf0().checker->in_collision({w.q, w.objects, {}}, data, {}, &hit) ||
             hit.second.find("table") == std::string::npos);
  }
  // The object stays 5 cm above where it was picked while the robot carries it.
  void float_during_carry() {
    const size_t g = first_with_action(path, GripperAction::Grasp), r = first_with_action(path, GripperAction::Release);
    ASSERT_GT(r, g + 2);
    Pose floating = path.waypoints[g].objects[0];
    floating.translation().z() += 0.05;
    for (size_t i = g + 1; i < r; ++i) path.waypoints[i].objects[0] = floating;
  }
  Path path = solved_path();
};

TEST_F(BrokenPath, ObjectTeleported) {
  // At one waypoint before the grasp the object is 10 cm away, then back: it jumps.
  path.waypoints[first_with_action(path, GripperAction::Grasp) / 2].objects[0].translation().x() += 0.1;
  expect_invalid(path, "YCBV_02 moves");
}

TEST_F(BrokenPath, WaypointInCollision) {
  // A waypoint before the grasp moves the arm to a (seeded random) configuration that hits the
  // table or the robot's support box. The first collision on the way there may be another one
  // (the arm sweeping through the object, when the waypoint is near it).
  put_into_table(path.waypoints[first_with_action(path, GripperAction::Grasp) / 2], 3);
  expect_invalid(path, "collision between ");
}

TEST_F(BrokenPath, ObjectLeftUnconstrained) {
  // While the robot carries it, the object stays 5 cm above where it was picked: it is neither
  // held (the gripper moves away) nor placed.
  float_during_carry();
  expect_invalid(path, "neither grasped nor placed");
}

TEST_F(BrokenPath, TheEarliestOfTwoFailuresIsReported) {
  // The samples are checked on every core, in chunks: a later failure found first must not win.
  // Early: an arm configuration hitting the table; late: the object floating during the carry.
  float_during_carry();
  const size_t g = first_with_action(path, GripperAction::Grasp);
  const ValidationReport late = validate_path(shelf0().scene, shelf0().vtask, path);
  ASSERT_FALSE(late.valid);
  EXPECT_NE(late.message.find("neither grasped nor placed"), std::string::npos) << late.message;

  put_into_table(path.waypoints[g / 2], 5);
  const ValidationReport early = validate_path(shelf0().scene, shelf0().vtask, path);
  ASSERT_FALSE(early.valid);
  EXPECT_NE(early.message.find("collision between "), std::string::npos) << early.message;
  EXPECT_LT(early.failure_t, late.failure_t);
  EXPECT_GT(early.failure_t, 0.0);
}

TEST_F(BrokenPath, WrongStart) {
  path.waypoints.front().q[0] += 0.1;
  expect_invalid(path, "does not start at its initial configuration");
}

TEST_F(BrokenPath, PlacedObjectMoved) {
  // Before the grasp the resting object slides 5 mm along the table: still placed, but moved.
  // Where the slide is spread over a long segment it is caught as a motion without a carrier.
  const size_t g = first_with_action(path, GripperAction::Grasp);
  for (size_t i = g / 2; i < path.waypoints.size() && i < g - 1; ++i) path.waypoints[i].objects[0].translation().y() += 0.005;
  expect_invalid(path, "YCBV_02 moves");
}

TEST(PlannerRegistry, NamesItsPlannersAndRefusesAnUnknownOne) {
  const std::vector<std::string> names = planner_names();
  EXPECT_NE(std::find(names.begin(), names.end(), "guided"), names.end());
  PlannerSettings s;
  EXPECT_EQ(make_planner(s)->name(), "guided");
  s.planner_name = "rrt-magic";
  try {
    make_planner(s);
    ADD_FAILURE() << "an unknown planner was made";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("rrt-magic"), std::string::npos) << what;
    EXPECT_NE(what.find("guided"), std::string::npos) << what;  // says what is known
  }
}

// The plan job keeps the planner's own path (the same as the planner gives alone), shortens it,
// and validates both.
TEST(PlanJob, PlansShortensAndValidates) {
  BenchmarkProblem& p = shelf0();
  PlannerSettings s;
  s.planner = params(7);
  s.shortcutting.max_attempts = 300;  // bounded by attempts, not time: reproducible
  const PlanReport r = run_plan_job(p.problem, s);
  ASSERT_TRUE(r.valid()) << r.plan.message << " / " << r.validation.message;
  EXPECT_EQ(r.planner, "guided");
  const PlanResult alone = p.plan(params(7));
  ASSERT_EQ(r.plan.path.waypoints.size(), alone.path.waypoints.size());
  for (size_t k = 0; k < alone.path.waypoints.size(); ++k)
    EXPECT_TRUE((r.plan.path.waypoints[k].q.array() == alone.path.waypoints[k].q.array()).all()) << "waypoint " << k;
  EXPECT_TRUE(r.planner_validation.valid) << r.planner_validation.message;
  EXPECT_TRUE(r.shortened);
  EXPECT_LT(r.validation.length.robot, r.planner_validation.length.robot);
  EXPECT_FALSE(r.feasibility.has_value());
}

TEST(PlanJob, AfterAFailureSaysWhichPickCannotBeDone) {
  BenchmarkProblem p("shelf_2", "panda", 0, demoplan::testdata::data_dir_with_2024_bottle(DEMOPLAN_DATA_DIR));
  PlannerSettings s;
  s.planner = params(1, 0.5);
  s.feasibility_samples = 40;
  const PlanReport r = run_plan_job(p.problem, s);
  EXPECT_FALSE(r.solved());
  ASSERT_TRUE(r.feasibility.has_value());
  ASSERT_EQ(r.feasibility->picks.size(), 3u);
  EXPECT_FALSE(r.feasibility->picks[1].feasible());  // the bottle
  EXPECT_NE(r.feasibility->summary(p.scene).find("pick 2 (YCBV_05) cannot be done"), std::string::npos);
}

TEST(PlanJob, ACancelledJobStopsWithoutADiagnosis) {
  BenchmarkProblem& p = shelf0();
  const std::atomic<bool> cancel{true};
  const PlanReport r = run_plan_job(p.problem, PlannerSettings{}, {}, &cancel);
  EXPECT_FALSE(r.solved());
  EXPECT_TRUE(r.plan.cancelled);
  EXPECT_FALSE(r.feasibility.has_value());
}

TEST(PlannerSettingsJson, RoundTripsAndNamesABadField) {
  PlannerSettings s;
  s.planner_name = "guided";
  s.planner.seed = 42;
  s.planner.time_limit = 12.5;
  s.planner.eta_sample_tree = 0.25;
  s.shortcut = false;
  s.shortcutting.time_limit = 3.0;
  s.feasibility_samples = 77;
  const Json j = planner_settings_to_json(s);
  const PlannerSettings back = planner_settings_from_json(JsonField(j, "project.demoplan"));
  EXPECT_EQ(back.planner_name, "guided");
  EXPECT_EQ(back.planner.seed, 42u);
  EXPECT_EQ(back.planner.time_limit, 12.5);
  EXPECT_EQ(back.planner.eta_sample_tree, 0.25);
  EXPECT_FALSE(back.shortcut);
  EXPECT_EQ(back.shortcutting.time_limit, 3.0);
  EXPECT_EQ(back.feasibility_samples, 77);
  Json bad = j;
  bad["time_limit_s"] = -1;
  try {
    planner_settings_from_json(JsonField(bad, "project.demoplan"));
    ADD_FAILURE() << "a negative time limit was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("time_limit_s"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("project.demoplan"), std::string::npos) << e.what();
  }
}
