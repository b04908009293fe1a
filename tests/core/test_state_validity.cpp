// Edge checks in bisection order give the verdict of a walk from one end to the other, and the
// collision they report is one found at one of the edge's samples.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "core/graph/state_validity.h"
#include "tests/core/planning_problem.h"

using namespace demoplan;

namespace {

// The reference: every sample from a to b in order, each checked alone; every pair that
// touches at some sample is added to `pairs`.
bool walk_free(const BenchmarkProblem& p, CollisionData& data, int state, const Eigen::VectorXd& a,
               const Eigen::VectorXd& b, double resolution, std::vector<CollisionPair>* pairs) {
  const int steps = static_cast<int>(std::ceil((b - a).norm() / resolution));
  SceneState s = scene_state(p.scene, p.graph, state, a);
  bool free = true;
  for (int k = 1; k < steps; ++k) {
    s.q = a + (b - a) * (static_cast<double>(k) / steps);
    const std::vector<CollisionPair> c = p.checker->collisions(s, data);
    pairs->insert(pairs->end(), c.begin(), c.end());
    free = free && c.empty();
  }
  return free;
}

}  // namespace

TEST(StateValidity, BisectionGivesTheVerdictOfAWalkOnRandomEdges) {
  const BenchmarkProblem p("shelf_2", "panda", 0);
  const double resolution = 0.005;
  const StateValidity validity(p.scene, p.graph, *p.checker, resolution);
  CollisionData data = p.checker->make_data();
  const Eigen::VectorXd lo = p.scene.robot.model.lower_limits(), hi = p.scene.robot.model.upper_limits();
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const int state = p.graph.start_state;
  int colliding = 0, free = 0, disagreements = 0;
  for (int i = 0; i < 400; ++i) {
    // Edges of the planner's step and longer, from random configurations, as the planner and
    // the shortcut make them.
    Eigen::VectorXd a(lo.size()), d(lo.size());
    for (int k = 0; k < lo.size(); ++k) a[k] = lo[k] + u(rng) * (hi[k] - lo[k]), d[k] = u(rng) - 0.5;
    const Eigen::VectorXd b = (a + d.normalized() * (0.1 + 1.4 * u(rng))).cwiseMax(lo).cwiseMin(hi);
    CollisionPair hit;
    std::vector<CollisionPair> pairs;
    const bool bisection = validity.segment_free(state, a, b, data, &hit);
    const bool walk = walk_free(p, data, state, a, b, resolution, &pairs);
    disagreements += bisection != walk;
    (bisection ? free : colliding) += 1;
    if (!bisection) {
      const bool seen = std::any_of(pairs.begin(), pairs.end(), [&](const CollisionPair& c) {
        return (c.first == hit.first && c.second == hit.second) || (c.first == hit.second && c.second == hit.first);
      });
      EXPECT_TRUE(seen) << "edge " << i << ": " << hit.first << " / " << hit.second << " touch at none of its samples";
    }
  }
  EXPECT_EQ(disagreements, 0);
  EXPECT_GT(colliding, 20);
  EXPECT_GT(free, 20);
}
