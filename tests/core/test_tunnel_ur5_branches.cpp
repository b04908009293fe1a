// tunnel_0 with the UR5 at base pose 2, the one benchmark instance the guided planner never
// solves: why. A UR arm reaches a wrist point in two shoulder branches. Let w be the wrist point
// (where the axes of joints 5 and 6 meet), s a point on the shoulder-lift axis (joint 2) and r the
// horizontal reach direction (the base axis crossed with joint 2's axis). g(q) = (w - s) . r is
// continuous along any motion, so a carry from a configuration with g > 0 to one with g < 0
// passes through g = 0: the wrist point in the plane of the base axis and the shoulder-lift axis
// (the shoulder singularity). This test measures, on the real scene, that the grasp and the
// release of the second pick are collision-free only on opposite branches (docs/benchmarks.md
// says what is known about the carry between them).
#include <gtest/gtest.h>

#include <iostream>
#include <map>
#include <random>

#include "core/graph/projector.h"
#include "core/graph/state_validity.h"
#include "core/model/kinematics.h"
#include "tests/core/planning_problem.h"

using namespace demoplan;

namespace {

// The revolute joints of the arm, base to flange.
std::vector<const Joint*> arm_joints(const RobotModel& m) {
  std::vector<const Joint*> out;
  for (const Joint* j : m.configuration_joints())
    if (j->type == JointType::Revolute || j->type == JointType::Continuous) out.push_back(j);
  return out;
}

// A point on each joint axis and its direction, in the world.
struct Axis {
  Eigen::Vector3d point, direction;
};
std::vector<Axis> axes(const Scene& scene, const Eigen::VectorXd& q) {
  PoseVector links;
  forward_kinematics(scene.robot.model, q, scene.robot.base, links);
  std::vector<Axis> out;
  for (const Joint* j : arm_joints(scene.robot.model)) {
    const Pose& frame = links[j->child_link];  // the joint frame is the child link's frame
    out.push_back({frame.translation(), (frame.linear() * j->axis).normalized()});
  }
  return out;
}

// Midpoint of the closest points of two lines (the axes of joints 5 and 6 meet on a UR).
Eigen::Vector3d closest_point(const Axis& a, const Axis& b) {
  const Eigen::Vector3d w0 = a.point - b.point;
  const double aa = a.direction.dot(a.direction), ab = a.direction.dot(b.direction), bb = b.direction.dot(b.direction);
  const double d = a.direction.dot(w0), e = b.direction.dot(w0), den = aa * bb - ab * ab;
  const double s = (ab * e - bb * d) / den, t = (aa * e - ab * d) / den;
  return 0.5 * ((a.point + s * a.direction) + (b.point + t * b.direction));
}

double shoulder_branch(const Scene& scene, const Eigen::VectorXd& q) {
  const std::vector<Axis> ax = axes(scene, q);
  const Eigen::Vector3d w = closest_point(ax[4], ax[5]);
  const Eigen::Vector3d reach = ax[0].direction.cross(ax[1].direction).normalized();
  return (w - ax[1].point).dot(reach);
}

struct Tunnel {
  BenchmarkProblem p{"tunnel_0", "ur5", 2};
  ConstraintProjector projector{p.scene, p.graph};
  StateValidity validity{p.scene, p.graph, *p.checker, 0.005};
};

Tunnel& tunnel() {
  static Tunnel t;
  return t;
}

}  // namespace

TEST(TunnelUr5Pose2, GraspAndReleaseOfTheSecondPickLieOnOppositeShoulderBranches) {
  Tunnel& t = tunnel();
  ASSERT_EQ(t.p.graph.picks.size(), 2u);
  const GraphPick& pick = t.p.graph.picks[1];
  std::mt19937_64 rng(1);
  CollisionData data = t.p.checker->make_data();
  int grasps = 0, releases = 0;
  for (size_t h = 0; h < pick.grasp_states.size(); ++h) {
    std::map<int, int> grasp_sign, release_sign;  // sign -> collision-free samples
    for (int k = 0; k < 300; ++k) {
      const TransitionSample g = t.projector.sample_on_transition(pick.grasp[h], rng);
      if (g.ok && t.validity.transition_free(g, data)) ++grasp_sign[shoulder_branch(t.p.scene, g.q_to()) > 0 ? 1 : -1];
      const TransitionSample r = t.projector.sample_on_transition(pick.release[h], rng);
      if (r.ok && t.validity.transition_free(r, data)) ++release_sign[shoulder_branch(t.p.scene, r.q_from()) > 0 ? 1 : -1];
    }
    const std::string name = t.p.graph.states[pick.grasp_states[h]].name;
    std::cerr << name << ": grasp branches " << grasp_sign[1] << " +, " << grasp_sign[-1] << " -; release "
              << release_sign[1] << " +, " << release_sign[-1] << " -\n";
    for (const auto& [sign, n] : grasp_sign) {
      grasps += n;
      if (n > 0) {
        EXPECT_EQ(release_sign[sign], 0) << name << ": a grasp and a release on the same branch";
      }
    }
    for (const auto& [sign, n] : release_sign) releases += n;
  }
  EXPECT_GT(grasps, 0);
  EXPECT_GT(releases, 0);
}
