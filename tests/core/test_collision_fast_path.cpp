// The checker's fast path (bounding spheres before FCL) answers exactly as FCL alone, on every
// benchmark scene: random, held-object, moved-object and near-boundary states.
#include <gtest/gtest.h>

#include <algorithm>
#include <ostream>
#include <random>

#include "core/scene/bounding_spheres.h"
#include "core/scene/geometry_bounds.h"
#include "tests/core/fast_path_agreement.h"

using namespace demoplan;

static const std::string kData = DEMOPLAN_DATA_DIR;

namespace {

struct SceneCase {
  std::string task, robot;
};

void PrintTo(const SceneCase& c, std::ostream* os) { *os << c.task << " " << c.robot; }

std::string case_name(const ::testing::TestParamInfo<SceneCase>& info) {
  return info.param.task + "_" + info.param.robot;
}

std::vector<SceneCase> benchmark_scenes() {
  std::vector<SceneCase> out;
  for (const std::string task : {"shelf_0", "shelf_1", "shelf_2", "tunnel_0", "waiter_0"}) {
    const BenchmarkTask t = load_benchmark_task(kData, task);
    for (const std::string robot : {"panda", "ur5", "kmr_iiwa"}) {
      const auto poses = benchmark_pose_ids(t, robot);
      if (std::find(poses.begin(), poses.end(), 0) != poses.end()) out.push_back({task, robot});
    }
  }
  return out;
}

class FastPathOnEveryScene : public ::testing::TestWithParam<SceneCase> {};

}  // namespace

TEST_P(FastPathOnEveryScene, AnswersAsFclAlone) {
  FastPathAgreement agreement(kData, GetParam().task, GetParam().robot, 0);
  const AgreementCounts c = agreement.run(20'000, 17);
  EXPECT_EQ(c.disagreements, 0) << c.first_disagreement;
  EXPECT_EQ(c.pair_mismatches, 0);
  // The comparison means something only with both answers, near the boundary too.
  EXPECT_GT(c.colliding, c.states / 20);
  EXPECT_LT(c.colliding, c.states - c.states / 20);
  EXPECT_GT(c.boundary, c.states / 10);
  if (!agreement.scene().objects.empty()) {
    EXPECT_GT(c.held, c.states / 10);
  }
}

INSTANTIATE_TEST_SUITE_P(BenchmarkScenes, FastPathOnEveryScene, ::testing::ValuesIn(benchmark_scenes()), case_name);

TEST(FastPath, EveryScenePoseZeroIsCovered) {
  // shelf_0..2 and tunnel_0 for all three robots, waiter_0 for the KMR.
  EXPECT_GE(benchmark_scenes().size(), 13u);
}

TEST(BoundingSpheres, CoverEveryPointOfEveryTriangle) {
  // A long thin strip (two triangles 1 m long, 1 cm wide) and a small far triangle.
  const std::vector<Eigen::Vector3d> v = {{0, 0, 0}, {1, 0, 0}, {1, 0.01, 0}, {0, 0.01, 0},
                                          {0.5, 0.3, 0.2}, {0.52, 0.3, 0.2}, {0.5, 0.32, 0.21}};
  const std::vector<std::array<std::uint32_t, 3>> t = {{0, 1, 2}, {0, 2, 3}, {4, 5, 6}};
  const SphereSet s = fit_bounding_spheres(v, t);
  ASSERT_FALSE(s.parts.empty());
  EXPECT_LE(s.parts.size(), 16u);
  ASSERT_EQ(s.children_begin.size(), s.parts.size() + 1);
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(0, 1);
  for (const auto& tri : t)
    for (int i = 0; i < 2000; ++i) {
      double a = u(rng), b = u(rng);
      if (a + b > 1) a = 1 - a, b = 1 - b;
      const Eigen::Vector3d p = v[tri[0]] + a * (v[tri[1]] - v[tri[0]]) + b * (v[tri[2]] - v[tri[0]]);
      EXPECT_LE((p - s.all.centre).norm(), s.all.radius);
      // By a part, and by one of that part's children (the finer level the pre-test uses).
      bool covered = false;
      for (size_t k = 0; k < s.parts.size(); ++k) {
        if ((p - s.parts[k].centre).norm() > s.parts[k].radius) continue;
        for (int c = s.children_begin[k]; c < s.children_begin[k + 1]; ++c)
          covered |= (p - s.children[c].centre).norm() <= s.children[c].radius;
      }
      EXPECT_TRUE(covered) << p.transpose();
    }
  // Split, the strip needs no sphere much wider than its pieces: far smaller than the whole.
  double largest = 0;
  for (const auto& sp : s.parts) largest = std::max(largest, sp.radius);
  EXPECT_LT(largest, 0.5 * s.all.radius);
}

TEST(GeometryBounds, SeparatedOnlyWhenApart) {
  const GeometryBound box = box_bound(Eigen::Vector3d(1.0, 0.2, 0.1));
  const GeometryBound ball = sphere_bound(0.05);
  const Pose box_pose = Pose::Identity();
  std::vector<Eigen::Vector3d> box_c(box.centre_count()), box_k(box.child_count());
  std::vector<Eigen::Vector3d> ball_c(ball.centre_count()), ball_k(ball.child_count());
  place_centres(box, box_pose, box_c.data());
  place_children(box, box_pose, box_k.data());
  auto at = [&](const Eigen::Vector3d& x) {
    Pose p = Pose::Identity();
    p.translation() = x;
    place_centres(ball, p, ball_c.data());
    place_children(ball, p, ball_k.data());
    const PlacedBound a{&ball, &p, ball_c.data(), ball_k.data()}, b{&box, &box_pose, box_c.data(), box_k.data()};
    return certainly_separated(a, b);
  };
  EXPECT_FALSE(at({0.0, 0.0, 0.0}));
  EXPECT_FALSE(at({0.0, 0.0, 0.0999}));    // 0.05 + 0.05 = 0.1: touching range
  EXPECT_TRUE(at({0.0, 0.0, 0.1001}));     // 0.1 mm above the top face
  EXPECT_TRUE(at({0.54, 0.14, 0.0}));      // off the corner edge: 5.66 cm > 5 cm
  EXPECT_FALSE(at({0.53, 0.13, 0.0}));     // 4.24 cm from the edge
}
