// Regrasps the demonstration does not show (core/planning/regrasp.h) on the one benchmark
// instance that needs one: tunnel_0 with the UR5 at base pose 2, whose second pick is grasped
// and released collision-free only on opposite shoulder branches (test_tunnel_ur5_branches).
// The guided planner puts the part down once and takes it again, and the validator accepts it.
#include <gtest/gtest.h>

#include "core/error.h"
#include "core/planning/plan_job.h"
#include "core/planning/regrasp.h"
#include "core/scene/support.h"
#include "tests/core/planning_problem.h"

using namespace demoplan;

namespace {

const BenchmarkProblem& tunnel() {
  static const BenchmarkProblem p("tunnel_0", "ur5", 2);
  return p;
}

std::vector<SupportPolygon> furniture_supports(const Scene& scene) {
  std::vector<SupportPolygon> out;
  for (const auto& s : support_polygons(scene))
    if (s.furniture >= 0) out.push_back(s);
  return out;
}

}  // namespace

TEST(Regrasp, SplitsThePickInTwoWithThePartPutDownBetween) {
  const BenchmarkProblem& p = tunnel();
  const Demonstration& demo = *p.problem.demonstration;
  ASSERT_EQ(demo.events.size(), 4u);
  Regrasp r;
  r.pick = 1;
  r.object = demo.events[2].object;
  r.placement = Pose::Identity();
  r.placement.translation() = Eigen::Vector3d(-0.3, 0.1, 0.8);
  const Demonstration d = with_regrasp(demo, r);
  EXPECT_TRUE(validate(d).empty());
  ASSERT_EQ(d.events.size(), 6u);
  EXPECT_EQ(d.events[3].type, EventType::Release);
  EXPECT_EQ(d.events[4].type, EventType::Grasp);
  EXPECT_TRUE(d.events[3].poses[static_cast<size_t>(r.object)].isApprox(r.placement));
  EXPECT_LE(d.events[2].frame, d.events[3].frame);
  EXPECT_LE(d.events[4].frame, d.events[5].frame);
  // Every other part stays where it is during the pick.
  for (size_t o = 0; o < d.object_ids.size(); ++o) {
    if (static_cast<int>(o) != r.object) {
      EXPECT_TRUE(d.events[3].poses[o].isApprox(demo.events[2].poses[o]));
    }
  }
  const ConstraintGraph g = build_constraint_graph(p.scene, d);
  EXPECT_EQ(g.picks.size(), 3u);
  EXPECT_EQ(g.placement_sequence.size(), 4u);
  r.pick = 2;
  EXPECT_THROW(with_regrasp(demo, r), InputError);
}

TEST(Regrasp, FindsPlacementsOnTheSupportsWhereThePartCanBePutDownAndTakenAgain) {
  const BenchmarkProblem& p = tunnel();
  std::mt19937_64 rng(1);
  const std::vector<Regrasp> found =
      find_regrasps(p.scene, *p.problem.demonstration, *p.checker, 1, 3, rng, StopCondition());
  ASSERT_EQ(found.size(), 3u);
  const auto supports = furniture_supports(p.scene);
  for (const Regrasp& r : found) {
    EXPECT_EQ(r.pick, 1);
    EXPECT_TRUE(check_placement(p.scene, supports, {}, r.object, r.placement).placed);
    EXPECT_NE(describe(p.scene, r).find("pick 2 ("), std::string::npos);
  }
}

TEST(Regrasp, TheGuidedPlannerSolvesTunnelUr5Pose2WithARegraspAndTheValidatorAcceptsIt) {
  const BenchmarkProblem& p = tunnel();
  PlannerParams params;
  params.seed = 2;
  const PlanResult r = GuidedPlanner(params).solve(p.problem, StopCondition(120.0));
  ASSERT_TRUE(r.solved) << r.message;
  EXPECT_NE(r.regrasp.find("pick 2 (YCBV_03): put down at"), std::string::npos) << r.regrasp;
  ASSERT_TRUE(r.graph);
  EXPECT_EQ(r.graph->picks.size(), 3u);
  EXPECT_GT(r.iterations, params.regrasp_after);
  const ValidationReport v = validate_path(p.scene, p.vtask, r.path);
  EXPECT_TRUE(v.valid) << v.message;
  EXPECT_EQ(v.grasps, 3);
}

// Seed 4 once took its regrasps for the wrong pick: with lazy links the start's tree seemed to
// reach the stalled pick's end through a link that collides (guided_planner.cpp, states_reached).
TEST(Regrasp, TheStalledPickIsFoundThroughCheckedLinksOnly) {
  const BenchmarkProblem& p = tunnel();
  PlannerParams params;
  params.seed = 4;
  ASSERT_TRUE(params.lazy_edges);
  const PlanResult r = GuidedPlanner(params).solve(p.problem, StopCondition(120.0));
  ASSERT_TRUE(r.solved) << r.message;
  EXPECT_NE(r.regrasp.find("pick 2 (YCBV_03): put down at"), std::string::npos) << r.regrasp;
  EXPECT_GT(r.rejected_links, 0);  // lazy links were cut on the way
  EXPECT_TRUE(validate_path(p.scene, p.vtask, r.path).valid);
}

TEST(Regrasp, PathsFoundBeforeTheRegraspsStartAreThoseWithoutThem) {
  const BenchmarkProblem p("shelf_1", "ur5", 0);
  PlannerParams with, without;
  with.seed = without.seed = 1;
  without.regrasp_after = 0;
  const PlanResult a = GuidedPlanner(with).solve(p.problem, StopCondition(60.0));
  const PlanResult b = GuidedPlanner(without).solve(p.problem, StopCondition(60.0));
  ASSERT_TRUE(a.solved && b.solved);
  EXPECT_LT(a.iterations, with.regrasp_after);
  EXPECT_TRUE(a.regrasp.empty());
  ASSERT_EQ(a.path.waypoints.size(), b.path.waypoints.size());
  for (size_t k = 0; k < a.path.waypoints.size(); ++k) EXPECT_EQ(a.path.waypoints[k].q, b.path.waypoints[k].q);
}
