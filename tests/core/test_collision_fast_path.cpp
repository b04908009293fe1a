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
  EXPECT_EQ(c.answer_only_disagreements, 0) << c.first_disagreement;
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

TEST(GeometryBounds, BoxesSeparatedOnlyWhenApart) {
  const GeometryBound cube = box_bound(Eigen::Vector3d::Ones());
  std::vector<Eigen::Vector3d> ca(cube.centre_count()), cb(cube.centre_count());
  auto apart = [&](const Pose& pa, const Pose& pb) {
    place_centres(cube, pa, ca.data());
    place_centres(cube, pb, cb.data());
    const PlacedBound a{&cube, &pa, ca.data(), nullptr}, b{&cube, &pb, cb.data(), nullptr};
    return certainly_separated(a, b);
  };
  auto pose = [](const Eigen::Vector3d& x, const Eigen::AngleAxisd& r) {
    Pose p = Pose::Identity();
    p.linear() = r.toRotationMatrix();
    p.translation() = x;
    return p;
  };
  const Eigen::AngleAxisd none(0.0, Eigen::Vector3d::UnitZ());
  const Pose origin = Pose::Identity();
  // Face to face: 0.1 mm apart, and touching.
  EXPECT_TRUE(apart(origin, pose({1.0001, 0.2, 0.3}, none)));
  EXPECT_FALSE(apart(origin, pose({0.9999, 0.2, 0.3}, none)));
  // A corner towards a face (45 degrees about z): the corner reaches 0.5 sqrt(2) from its centre.
  const Eigen::AngleAxisd yaw(M_PI / 4, Eigen::Vector3d::UnitZ());
  EXPECT_TRUE(apart(origin, pose({0.5 + 0.5 * std::sqrt(2.0) + 1e-4, 0, 0}, yaw)));
  EXPECT_FALSE(apart(origin, pose({0.5 + 0.5 * std::sqrt(2.0) - 1e-4, 0, 0}, yaw)));
  // Edge across edge: only the cross product of the two edges separates them (the spheres and
  // the face normals do not).
  const Pose a = pose({0, 0, 0}, Eigen::AngleAxisd(M_PI / 4, Eigen::Vector3d::UnitY()));
  const double reach = std::sqrt(2.0);  // top edge of a plus bottom edge of b
  EXPECT_TRUE(apart(a, pose({0, 0, reach + 1e-4}, Eigen::AngleAxisd(M_PI / 4, Eigen::Vector3d::UnitX()))));
  EXPECT_FALSE(apart(a, pose({0, 0, reach - 1e-4}, Eigen::AngleAxisd(M_PI / 4, Eigen::Vector3d::UnitX()))));
}

TEST(GeometryBounds, TouchingOnlyWhenACornerIsInside) {
  const GeometryBound cube = box_bound(Eigen::Vector3d::Ones());
  // A mesh: one triangle 0.4 m wide, in its own frame around the origin.
  const std::vector<Eigen::Vector3d> vertices{{-0.2, 0, 0}, {0.2, 0, 0}, {0, 0.2, 0}};
  const GeometryBound tri = mesh_bound(std::make_shared<SphereSet>(fit_bounding_spheres(vertices, {{0, 1, 2}})));
  ASSERT_EQ(tri.spheres->witnesses.size(), 3u);
  auto at = [](double x, double y, double z) {
    Pose p = Pose::Identity();
    p.translation() = Eigen::Vector3d(x, y, z);
    return p;
  };
  auto touching = [&](const GeometryBound& ga, const Pose& pa, const GeometryBound& gb, const Pose& pb) {
    std::vector<Eigen::Vector3d> ca(ga.centre_count()), cb(gb.centre_count());
    place_centres(ga, pa, ca.data());
    place_centres(gb, pb, cb.data());
    return certainly_touching({&ga, &pa, ca.data(), nullptr}, {&gb, &pb, cb.data(), nullptr});
  };
  const Pose origin = Pose::Identity();
  // Box corners: one 0.1 mm inside the other box, then 0.1 mm outside.
  EXPECT_TRUE(touching(cube, origin, cube, at(0.9999, 0.9999, 0.9999)));
  EXPECT_FALSE(touching(cube, origin, cube, at(1.0001, 0.9999, 0.9999)));
  // The triangle's corner (-0.2, 0, 0) just inside the cube's face x = 0.5, and just outside.
  // A triangle through the cube with every corner outside: an edge crosses the cube (proven,
  // test_geometry_bounds_edges.cpp), or none does: FCL would find contact, this test cannot say.
  EXPECT_TRUE(touching(tri, at(0.6999, 0, 0), cube, origin));
  EXPECT_TRUE(touching(cube, origin, tri, at(0.6999, 0, 0)));
  EXPECT_FALSE(touching(tri, at(0.7001, 0, 0), cube, origin));
  const Pose across = at(0, 0, 0.5) * Pose(Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitX()));
  const GeometryBound big = mesh_bound(std::make_shared<SphereSet>(
      fit_bounding_spheres({{-1, -0.75, 0}, {1, -0.75, 0}, {0, 0.75, 0}}, {{0, 1, 2}})));
  EXPECT_TRUE(touching(big, origin, cube, origin));  // through the cube's middle, an edge across it
  const GeometryBound huge = mesh_bound(std::make_shared<SphereSet>(
      fit_bounding_spheres({{-3, -2, 0}, {3, -2, 0}, {0, 3, 0}}, {{0, 1, 2}})));
  EXPECT_FALSE(touching(huge, origin, cube, origin));  // the cube inside it, every edge 1 m away
  EXPECT_FALSE(touching(tri, at(0, 0, 0.45) * across, tri, origin));  // two meshes: never
}
