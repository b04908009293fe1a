// state_runs: the single-state motions of a path, on a path made by hand and on a planned one.
#include <gtest/gtest.h>

#include "core/path/state_runs.h"

using namespace demoplan;

namespace {

Waypoint at(double x, int state, bool approach = false) {
  Waypoint w;
  w.q = Eigen::VectorXd::Constant(2, x);
  w.state = state;
  w.approach = approach;
  return w;
}

}  // namespace

TEST(StateRuns, CutsAtStateChangesAndLeavesOutTheStraightApproaches) {
  Path p;
  // Transit in P0 to the pre-grasp (2), approach to the grasp (3), transfer in G1 to the release
  // (5), retreat (6), transit in P0 again.
  p.waypoints = {at(0, 0), at(1, 0), at(2, 0, true), at(3, 1), at(4, 1), at(5, 1, true), at(6, 0), at(7, 0)};
  const std::vector<StateRun> runs = state_runs(p);
  ASSERT_EQ(runs.size(), 3u);
  EXPECT_EQ(runs[0].state, 0);
  EXPECT_EQ(runs[0].first, 0u);
  EXPECT_EQ(runs[0].last, 2u);
  EXPECT_EQ(runs[1].state, 1);
  EXPECT_EQ(runs[1].first, 3u);
  EXPECT_EQ(runs[1].last, 5u);
  EXPECT_EQ(runs[2].state, 0);
  EXPECT_EQ(runs[2].first, 6u);
  EXPECT_EQ(runs[2].last, 7u);
}

TEST(StateRuns, AnApproachOfSeveralWaypointsAndARunThatDoesNotMoveGiveNoRun) {
  Path p;
  // An approach followed in three steps (1 -> 4), then a run whose ends coincide (4 -> 5 -> 4).
  p.waypoints = {at(0, 0), at(1, 0, true), at(1.1, 0, true), at(1.2, 0, true), at(2, 1), at(2.5, 1), at(2, 1)};
  const std::vector<StateRun> runs = state_runs(p);
  ASSERT_EQ(runs.size(), 1u);
  EXPECT_EQ(runs[0].first, 0u);
  EXPECT_EQ(runs[0].last, 1u);
  EXPECT_TRUE(state_runs(Path{}).empty());
}
