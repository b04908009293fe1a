// Single-state problems cut from a guided solution of shelf_0 (Panda, pose 1): the cut is
// consistent with the path, our RRT-Connect and (when built in) OMPL's planners solve one with a
// path our independent check accepts, OMPL reproduces per seed, and the check rejects a path
// through an obstacle.
#include <gtest/gtest.h>

#include <algorithm>

#include "core/error.h"
#include "core/graph/state_validity.h"
#include "core/path/state_runs.h"
#include "core/planning/single_state/single_state.h"
#include "core/planning/single_state/single_state_check.h"
#include "tests/core/planning_problem.h"

using namespace demoplan;

namespace {

BenchmarkProblem& shelf0() {
  static BenchmarkProblem p("shelf_0", "panda", 1);
  return p;
}

const Path& solved_path() {
  static const Path path = [] {
    PlannerParams params;
    params.seed = 1;
    params.time_limit = 30.0;
    const PlanResult r = shelf0().plan(params);
    EXPECT_TRUE(r.solved) << r.message;
    return r.path;
  }();
  return path;
}

struct Problem {
  int state = -1;
  Eigen::VectorXd from, to;
};

// The run of the solved path whose straight move collides the longest way (a real search), or
// the longest run when every straight move is free.
Problem hardest_run() {
  const Path& path = solved_path();
  BenchmarkProblem& p = shelf0();
  const StateValidity validity(p.scene, p.graph, *p.checker, 0.005);
  CollisionData data = p.checker->make_data();
  Problem best;
  double best_score = -1;
  for (const StateRun& r : state_runs(path)) {
    const Eigen::VectorXd& a = path.waypoints[r.first].q;
    const Eigen::VectorXd& b = path.waypoints[r.last].q;
    const double score = (b - a).norm() + (validity.segment_free(r.state, a, b, data) ? 0.0 : 100.0);
    if (score > best_score) best_score = score, best = {r.state, a, b};
  }
  return best;
}

void expect_solves(const std::string& planner) {
  const Problem s = hardest_run();
  ASSERT_GE(s.state, 0);
  const SingleStateResult r =
      solve_single_state(shelf0().problem, s.state, s.from, s.to, planner, StopCondition(20.0), 1);
  ASSERT_TRUE(r.solved) << planner << ": " << r.message;
  EXPECT_GE(r.path.size(), 2u);
  EXPECT_GT(r.time_s, 0.0);
  EXPECT_GE(r.length(), (s.to - s.from).norm() - 1e-9);
  const SingleStateCheck check = check_single_state_path(shelf0().problem, s.state, r.path, s.from, s.to);
  EXPECT_TRUE(check.valid) << planner << ": " << check.message;
}

}  // namespace

TEST(SingleStateRuns, AreConsistentWithTheSolvedPath) {
  const Path& path = solved_path();
  const std::vector<StateRun> runs = state_runs(path);
  ASSERT_GE(runs.size(), 3u);  // transit to the pick, transfer, transit home at least
  const ConstraintGraph& g = shelf0().graph;
  bool transit = false, transfer = false;
  size_t previous_last = 0;
  for (size_t i = 0; i < runs.size(); ++i) {
    const StateRun& r = runs[i];
    ASSERT_LT(r.first, r.last);
    ASSERT_LT(r.last, path.waypoints.size());
    if (i > 0) {
      EXPECT_GE(r.first, previous_last);  // in order, not overlapping
    }
    previous_last = r.last;
    for (size_t k = r.first; k <= r.last; ++k) EXPECT_EQ(path.waypoints[k].state, r.state);
    for (size_t k = r.first; k < r.last; ++k) EXPECT_FALSE(path.waypoints[k].approach);
    (g.states[r.state].kind == StateKind::Grasp ? transfer : transit) = true;
  }
  EXPECT_TRUE(transit);
  EXPECT_TRUE(transfer);
  // The first run starts where the path does, the last ends where it does.
  EXPECT_EQ(runs.front().first, 0u);
  EXPECT_EQ(runs.back().last, path.waypoints.size() - 1);
}

TEST(SingleState, OurRrtConnectSolvesARunOfTheGuidedSolution) { expect_solves(kOurSingleStatePlanner); }

TEST(SingleState, OmplRrtConnectSolvesTheSameRun) {
  if (!ompl_available()) GTEST_SKIP() << "built without OMPL";
  expect_solves("ompl-rrtconnect");
}

TEST(SingleState, OmplPrmAndKpieceSolveTheSameRun) {
  if (!ompl_available()) GTEST_SKIP() << "built without OMPL";
  expect_solves("ompl-prm");
  expect_solves("ompl-kpiece");
}

TEST(SingleState, OmplReproducesItsPathPerSeed) {
  if (!ompl_available()) GTEST_SKIP() << "built without OMPL";
  const Problem s = hardest_run();
  auto solve = [&](std::uint64_t seed) {
    return solve_single_state(shelf0().problem, s.state, s.from, s.to, "ompl-rrtconnect", StopCondition(20.0), seed);
  };
  const SingleStateResult a = solve(3), b = solve(3);
  ASSERT_TRUE(a.solved && b.solved);
  ASSERT_EQ(a.path.size(), b.path.size());
  for (size_t k = 0; k < a.path.size(); ++k) EXPECT_EQ(a.path[k], b.path[k]) << k;
}

TEST(SingleState, TheCheckRejectsAStraightMoveThroughAnObstacle) {
  const Problem s = hardest_run();
  BenchmarkProblem& p = shelf0();
  const StateValidity validity(p.scene, p.graph, *p.checker, 0.01);
  CollisionData data = p.checker->make_data();
  if (validity.segment_free(s.state, s.from, s.to, data)) GTEST_SKIP() << "every run of this path is a free straight move";
  const SingleStateCheck c = check_single_state_path(p.problem, s.state, {s.from, s.to}, s.from, s.to);
  EXPECT_FALSE(c.valid);
  EXPECT_NE(c.message.find("edge 0-1 collides"), std::string::npos) << c.message;
  // And a path that does not end where asked.
  EXPECT_FALSE(check_single_state_path(p.problem, s.state, {s.from, s.from}, s.from, s.to).valid);
}

TEST(SingleState, RefusesAnUnknownPlannerAndOmplWhenNotBuiltIn) {
  const Problem s = hardest_run();
  EXPECT_THROW(solve_single_state(shelf0().problem, s.state, s.from, s.to, "rrt-star", StopCondition(1.0), 1),
               InputError);
  const auto names = single_state_planner_names();
  EXPECT_EQ(std::count(names.begin(), names.end(), "ompl-rrtconnect"), ompl_available() ? 1 : 0);
  if (!ompl_available()) {
    EXPECT_THROW(solve_single_state(shelf0().problem, s.state, s.from, s.to, "ompl-rrtconnect", StopCondition(1.0), 1),
                 InputError);
  }
}
