// The mobile base's seeds for grasps and releases: the base placed from the handle's reach
// (base_sampler.h). On the KMR iiwa's shelf_2 the uniform seed leaves the base against the
// shelf or the table, or the handle out of reach; with the base sampler pick 2 (YCBV_05 from the
// table into the shelf) has a handle that grasps and releases collision-free. Pick 3 (YCBV_12)
// still has none: its releases put the hand or wrist into YCBV_02 or YCBV_05 already in the shelf.
#include <gtest/gtest.h>

#include "core/demo/benchmark_demonstration.h"
#include "core/demo/benchmark_scene.h"
#include "core/geometry/box_overlap.h"
#include "core/graph/pick_feasibility.h"
#include "core/graph/state_validity.h"
#include "core/model/mobile_base.h"

using namespace demoplan;

namespace {

struct Instance {
  Instance(const std::string& task_name, const std::string& robot, int pose)
      : task(load_benchmark_task(DEMOPLAN_DATA_DIR, task_name)),
        scene(build_benchmark_scene(task, robot, pose)),
        graph(build_constraint_graph(scene, demonstration_from_benchmark(task, scene, PoseSource::Subgoals))),
        checker(scene) {}
  BenchmarkTask task;
  Scene scene;
  ConstraintGraph graph;
  CollisionChecker checker;
};

// Collision-free transition samples of one pick's grasps and releases, over every handle.
int collision_free(const Instance& in, const ConstraintProjector& projector, int pick, int samples) {
  const StateValidity validity(in.scene, in.graph, in.checker);
  CollisionData data = in.checker.make_data();
  std::mt19937_64 rng(7);
  const GraphPick& p = in.graph.picks[static_cast<size_t>(pick)];
  int free = 0;
  for (const auto& ts : {p.grasp, p.release})
    for (int t : ts)
      for (int k = 0; k < samples; ++k) {
        const TransitionSample s = projector.sample_on_transition(t, rng);
        free += s.ok && validity.transition_free(s, data);
      }
  return free;
}

}  // namespace

TEST(BoxOverlap, SeparatesAlongFaceAndEdgeAxes) {
  const Eigen::Vector3d half(0.5, 0.5, 0.5);
  Pose b = Pose::Identity();
  b.translation() = Eigen::Vector3d(0.9, 0, 0);
  EXPECT_TRUE(boxes_overlap(Pose::Identity(), half, b, half));
  b.translation() = Eigen::Vector3d(1.1, 0, 0);
  EXPECT_FALSE(boxes_overlap(Pose::Identity(), half, b, half));
  // Turned 45 degrees about z, its corner reaches 0.707 toward the other: apart at 1.25, not at 1.15.
  b.linear() = Eigen::AngleAxisd(M_PI / 4, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  b.translation() = Eigen::Vector3d(1.15, 0, 0);
  EXPECT_TRUE(boxes_overlap(Pose::Identity(), half, b, half));
  b.translation() = Eigen::Vector3d(1.25, 0, 0);
  EXPECT_FALSE(boxes_overlap(Pose::Identity(), half, b, half));
  // Edge against edge: turned about z and about x, only an edge-edge axis separates them.
  b.linear() = (Eigen::AngleAxisd(M_PI / 4, Eigen::Vector3d::UnitZ()) * Eigen::AngleAxisd(M_PI / 4, Eigen::Vector3d::UnitY()))
                   .toRotationMatrix();
  b.translation() = Eigen::Vector3d(1.2, 1.2, 0);
  EXPECT_FALSE(boxes_overlap(Pose::Identity(), half, b, half));
}

TEST(MobileBase, FoundOnTheKmrOnlyAndPlacesTheBody) {
  const Instance kmr("shelf_2", "kmr_iiwa", 0);
  const RobotModel& m = kmr.scene.robot.model;
  const auto base = find_mobile_base(m);
  ASSERT_TRUE(base);
  EXPECT_EQ(m.links[static_cast<size_t>(base->body)].name, "kmr_link");
  EXPECT_EQ(base->x, 0);
  EXPECT_EQ(base->y, 1);
  EXPECT_EQ(base->yaw, 2);
  Eigen::VectorXd q = Eigen::VectorXd::Zero(m.nq);
  base->set_body_pose(m, kmr.scene.robot.base, 0.4, -1.2, 2.0, q);
  const Pose body = base->body_pose(m, q, kmr.scene.robot.base);
  EXPECT_NEAR(body.translation().x(), 0.4, 1e-9);
  EXPECT_NEAR(body.translation().y(), -1.2, 1e-9);
  EXPECT_NEAR(std::atan2(body.linear()(1, 0), body.linear()(0, 0)), 2.0, 1e-9);
  for (const char* robot : {"panda", "ur5"}) {
    const Instance fixed("shelf_2", robot, 0);
    EXPECT_FALSE(find_mobile_base(fixed.scene.robot.model)) << robot;
    EXPECT_EQ(ConstraintProjector(fixed.scene, fixed.graph).base_sampler(), nullptr) << robot;
  }
}

// Pick 2 of shelf_2 (YCBV_05 from the table into the shelf): seeds from the handle's reach give
// several times the collision-free grasps and releases of uniform seeds.
TEST(BaseSampler, PutsTheHandleInReachWithTheBodyClear) {
  const Instance kmr("shelf_2", "kmr_iiwa", 0);
  ProjectorOptions uniform;
  uniform.uniform_base_fraction = 1.0;
  const ConstraintProjector reach(kmr.scene, kmr.graph), old(kmr.scene, kmr.graph, uniform);
  ASSERT_NE(reach.base_sampler(), nullptr);
  const int samples = 40;
  const int with_reach = collision_free(kmr, reach, 1, samples);
  const int with_uniform = collision_free(kmr, old, 1, samples);
  std::printf("pick 2 collision-free samples: base sampler %d, uniform %d\n", with_reach, with_uniform);
  EXPECT_GT(with_reach, 0);
  EXPECT_GT(with_reach, 3 * with_uniform);

  // The body is clear of the furniture at every base it proposes, and the seed's gripper lies
  // on the handle up to the reach map's height tolerance.
  const BaseSampler& sampler = *reach.base_sampler();
  std::mt19937_64 rng(3);
  int placed = 0;
  for (int t : kmr.graph.picks[1].grasp) {
    int link = -1;
    const Pose target = reach.handle_target(t, &link);
    for (int k = 0; k < 20; ++k) {
      Eigen::VectorXd q = kmr.graph.q_start;
      if (!sampler.sample(target, link, q, rng)) continue;
      ++placed;
      EXPECT_TRUE(sampler.clear_of_furniture(q));
      const Pose at = gripper_pose(kmr.scene, q);
      EXPECT_LT((at.translation() - target.translation()).head<2>().norm(), 1e-6);
      EXPECT_LT(std::abs(at.translation().z() - target.translation().z()), 0.05 + 1e-9);
    }
  }
  EXPECT_GT(placed, 0);
}

// Before the base sampler picks 2 and 3 had no handle (docs/benchmarks.md); now pick 2 has.
TEST(BaseSampler, ThePicksOfShelf2ThatTheBaseCostTheKmrAreFeasible) {
  const Instance kmr("shelf_2", "kmr_iiwa", 0);
  const FeasibilityReport r = assess_picks(kmr.scene, kmr.graph, kmr.checker, 60, 1);
  std::printf("%s", r.summary(kmr.scene).c_str());
  ASSERT_EQ(r.picks.size(), 3u);
  EXPECT_TRUE(r.picks[0].feasible()) << r.picks[0].reason;
  EXPECT_TRUE(r.picks[1].feasible()) << r.picks[1].reason;
  EXPECT_FALSE(r.picks[2].feasible());
  EXPECT_NE(r.picks[2].reason.find("in collision: object/YCBV_02 / robot/panda_hand"), std::string::npos) << r.picks[2].reason;
}
