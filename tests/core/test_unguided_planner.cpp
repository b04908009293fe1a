// The unguided manipulation planner (M-RRT as HPP searches) on real benchmark scenes: it solves
// the one-object shelf without the demonstration's placements and its path passes the
// validator; the resting poses it releases parts at pass the benchmark's placement test.
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <set>

#include "core/planning/plan_job.h"
#include "core/planning/unguided_planner.h"
#include "core/scene/resting_pose_sampler.h"
#include "tests/core/planning_problem.h"

using namespace demoplan;

TEST(UnguidedPlanner, SolvesTheOneObjectShelfWithAValidPathInStatesOfItsOwn) {
  const BenchmarkProblem p("shelf_0", "panda", 0);
  PlannerParams params;
  params.seed = 1;
  const PlanResult r = UnguidedPlanner(params).solve(p.problem, StopCondition(60.0));
  ASSERT_TRUE(r.solved) << r.message;
  ASSERT_TRUE(r.graph);
  const ValidationReport v = validate_path(p.scene, p.vtask, r.path);
  EXPECT_TRUE(v.valid) << v.message;
  EXPECT_EQ(v.grasps, 1);
  // It knew the start and goal placements only: its graph starts with those two states.
  EXPECT_EQ(r.graph->states[0].name, "start");
  EXPECT_EQ(r.graph->states[1].name, "goal");
  for (const Waypoint& w : r.path.waypoints) {
    ASSERT_LT(w.state, static_cast<int>(r.graph->states.size()));
    EXPECT_EQ(w.state_name, r.graph->states[w.state].name);
  }
  EXPECT_EQ(r.path.waypoints.front().state_name, "start");
  EXPECT_EQ(r.path.waypoints.back().state_name, "goal");
}

TEST(UnguidedPlanner, ThePlanJobShortensItsPathInItsOwnGraphAndValidatesIt) {
  const BenchmarkProblem p("shelf_0", "panda", 0);
  PlannerSettings settings;
  settings.planner_name = "unguided";
  settings.planner.seed = 2;
  const PlanReport r = run_plan_job(p.problem, settings);
  ASSERT_TRUE(r.solved()) << r.plan.message;
  EXPECT_TRUE(r.valid()) << r.validation.message;
  EXPECT_TRUE(r.shortened) << r.shortcut_rejection;
  EXPECT_LT(r.shortcut.length_after, r.shortcut.length_before);
}

TEST(UnguidedPlanner, SameSeedSamePath) {
  const BenchmarkProblem p("shelf_0", "panda", 0);
  PlannerParams params;
  params.seed = 3;
  const PlanResult a = UnguidedPlanner(params).solve(p.problem, StopCondition(60.0));
  const PlanResult b = UnguidedPlanner(params).solve(p.problem, StopCondition(60.0));
  ASSERT_TRUE(a.solved && b.solved);
  ASSERT_EQ(a.path.waypoints.size(), b.path.waypoints.size());
  for (size_t k = 0; k < a.path.waypoints.size(); ++k) EXPECT_EQ(a.path.waypoints[k].q, b.path.waypoints[k].q);
}

TEST(RestingPoseSampler, PosesRestOnSupportsAnywhereAndTurnedAnyWay) {
  const BenchmarkProblem p("shelf_1", "panda", 0);
  const RestingPoseSampler sampler(p.scene);
  ASSERT_FALSE(sampler.empty());
  std::vector<SupportPolygon> supports;
  for (const auto& s : support_polygons(p.scene))
    if (s.furniture >= 0) supports.push_back(s);
  std::mt19937_64 rng(7);
  std::set<int> used_supports;
  double min_yaw = 10, max_yaw = -10;
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(1e9), hi = -lo;
  int placed = 0;
  for (int k = 0; k < 200; ++k) {
    const auto pose = sampler.sample(0, rng);
    if (!pose) continue;
    ++placed;
    const PlacementCheck r = check_placement(p.scene, supports, {}, 0, *pose);
    ASSERT_TRUE(r.placed) << "sample " << k;
    used_supports.insert(r.support);
    const double yaw = std::atan2((*pose).linear()(1, 0), (*pose).linear()(0, 0));
    min_yaw = std::min(min_yaw, yaw), max_yaw = std::max(max_yaw, yaw);
    lo = lo.cwiseMin(pose->translation()), hi = hi.cwiseMax(pose->translation());
  }
  EXPECT_GT(placed, 150);
  EXPECT_GE(used_supports.size(), 2u);  // the table and the shelf's boards
  EXPECT_GT(max_yaw - min_yaw, 5.0);    // turned all the way round the normal
  EXPECT_GT((hi - lo).head<2>().minCoeff(), 0.2);  // spread over the surfaces, not one spot
}

// Releases and grasps add states while references into the state list are alive, and drop them
// again when the edge fails: a long search must run clean (it did not: a release read a moved
// state; the sanitizer build is what catches that) and keep only states it reached.
TEST(UnguidedPlanner, KeepsOnlyTheStatesItReachedThroughALongSearch) {
  const BenchmarkProblem p("tunnel_0", "panda", 0);
  PlannerParams params;
  params.seed = 1;
  params.max_iterations = 1200;  // deterministic: the iteration limit ends it, not the clock
  const PlanResult r = UnguidedPlanner(params).solve(p.problem, StopCondition(600.0));
  ASSERT_TRUE(r.graph);
  std::cerr << r.iterations << " iterations, " << r.graph->states.size() << " states\n";
  EXPECT_GT(r.graph->states.size(), 4u);
  ASSERT_EQ(r.state_nodes.size(), r.graph->states.size());
  for (size_t s = 0; s < r.state_nodes.size(); ++s) EXPECT_GT(r.state_nodes[s], 0u) << r.graph->states[s].name;
  for (const GraphTransition& t : r.graph->transitions) {
    EXPECT_LT(t.from, static_cast<int>(r.graph->states.size()));
    EXPECT_LT(t.to, static_cast<int>(r.graph->states.size()));
  }
  if (r.solved) {
    const ValidationReport v = validate_path(p.scene, p.vtask, r.path);
    EXPECT_TRUE(v.valid) << v.message;
  } else {
    EXPECT_NE(r.message.find("iteration limit"), std::string::npos) << r.message;
  }
}
