// Contact proven by an edge (geometry_bounds.h, certainly_touching): a mesh's triangle edge or a
// box's edge that crosses a solid primitive deeper than the margin. The proof must never say
// "touching" where FCL, as the checker calls it, says free; and it must fire where an arm
// crosses a thin board with no corner inside.
#include <fcl/fcl.h>
#include <gtest/gtest.h>

#include <random>

#include "core/scene/bounding_spheres.h"
#include "core/scene/geometry_bounds.h"

using namespace demoplan;

namespace {

using Vec = Eigen::Vector3d;
using Triangles = std::vector<std::array<std::uint32_t, 3>>;

// A mesh as the checker holds it: FCL's BVH and the fitted bound, from the same vertices.
struct Mesh {
  GeometryBound bound;
  std::shared_ptr<fcl::CollisionGeometryd> fcl;
};

Mesh make_mesh(const std::vector<Vec>& v, const Triangles& t) {
  auto bvh = std::make_shared<fcl::BVHModel<fcl::OBBRSSd>>();
  std::vector<fcl::Triangle> ft;
  for (const auto& x : t) ft.emplace_back(x[0], x[1], x[2]);
  bvh->beginModel(static_cast<int>(t.size()), static_cast<int>(v.size()));
  bvh->addSubModel(v, ft);
  bvh->endModel();
  return {mesh_bound(std::make_shared<SphereSet>(fit_bounding_spheres(v, t))), bvh};
}

// A square tube along z, `side` wide and `length` long, open at the ends: 8 triangles whose long
// edges run its whole length (like the UR5's upper arm).
Mesh tube(double side, double length) {
  const double s = side / 2, h = length / 2;
  std::vector<Vec> v;
  for (double z : {-h, h})
    for (const auto& [x, y] : std::vector<std::pair<double, double>>{{-s, -s}, {s, -s}, {s, s}, {-s, s}}) v.emplace_back(x, y, z);
  Triangles t;
  for (std::uint32_t i = 0; i < 4; ++i) {
    const std::uint32_t j = (i + 1) % 4;
    t.push_back({i, j, j + 4});
    t.push_back({i, j + 4, i + 4});
  }
  return make_mesh(v, t);
}

struct Placed {
  const GeometryBound* bound;
  Pose pose;
  std::vector<Vec> centres;
  Placed(const GeometryBound& b, const Pose& p) : bound(&b), pose(p), centres(b.centre_count()) {
    place_centres(b, pose, centres.data());
  }
  PlacedBound placed() { return {bound, &pose, centres.data(), nullptr}; }
};

bool touching(const GeometryBound& a, const Pose& pa, const GeometryBound& b, const Pose& pb) {
  Placed x(a, pa), y(b, pb);
  return certainly_touching(x.placed(), y.placed());
}

bool fcl_collides(const std::shared_ptr<fcl::CollisionGeometryd>& a, const Pose& pa,
                  const std::shared_ptr<fcl::CollisionGeometryd>& b, const Pose& pb) {
  fcl::CollisionObjectd oa(a, pa), ob(b, pb);
  fcl::CollisionRequestd request;
  fcl::CollisionResultd result;
  return fcl::collide(&oa, &ob, request, result) > 0;
}

Pose translation(double x, double y, double z) {
  Pose p = Pose::Identity();
  p.translation() = Vec(x, y, z);
  return p;
}

// A solid primitive, as the fast path bounds it and as FCL holds it.
struct Solid {
  GeometryBound bound;
  std::shared_ptr<fcl::CollisionGeometryd> fcl;
};

Pose random_pose(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(-1, 1);
  Pose p = Pose::Identity();
  p.linear() = Eigen::Quaterniond(Eigen::Vector4d(u(rng), u(rng), u(rng), u(rng)).normalized()).toRotationMatrix();
  p.translation() = Vec(u(rng), u(rng), u(rng));
  return p;
}

// A point on the surface of the primitive (in its frame) and the outward normal there.
std::pair<Vec, Vec> surface_point(const GeometryBound& p, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(-1, 1);
  const Vec dir = Vec(u(rng), u(rng), u(rng)).normalized();
  switch (p.kind) {
    case GeometryBound::Kind::Box: {
      Vec x = Vec(u(rng), u(rng), u(rng)).cwiseProduct(p.half);
      const int k = static_cast<int>(rng() % 3);
      const double side = rng() % 2 ? 1.0 : -1.0;
      x[k] = side * p.half[k];
      if (rng() % 3 == 0) {  // near an edge too
        const int m = (k + 1) % 3;
        x[m] = (rng() % 2 ? 1.0 : -1.0) * p.half[m];
      }
      return {x, side * Vec::Unit(k)};
    }
    case GeometryBound::Kind::Cylinder: {
      if (rng() % 3 == 0) {  // a cap
        const double side = rng() % 2 ? 1.0 : -1.0;
        const double r = p.half.x() * std::sqrt(0.5 * (u(rng) + 1)), a = M_PI * u(rng);
        return {Vec(r * std::cos(a), r * std::sin(a), side * p.half.z()), side * Vec::UnitZ()};
      }
      const double a = M_PI * u(rng);
      const Vec n(std::cos(a), std::sin(a), 0.0);
      return {p.half.x() * n + Vec(0, 0, u(rng) * p.half.z()), n};
    }
    default:
      return {p.half.x() * dir, dir};
  }
}

}  // namespace

TEST(GeometryBounds, EdgeProvesContactThroughAThinBoard) {
  // A 25 mm board and a tube 6 cm wide, 50 cm long crossing it: every corner of the tube lies
  // 23.75 cm from the board, so only an edge can prove the contact FCL finds.
  const GeometryBound board_bound = box_bound(Vec(1.0, 1.0, 0.025));
  const auto board = std::make_shared<fcl::Boxd>(1.0, 1.0, 0.025);
  const Mesh arm = tube(0.06, 0.5);
  ASSERT_EQ(arm.bound.spheres->edges.size(), 16u);  // 4 long sides, 4 diagonals, 8 end edges
  EXPECT_NEAR((arm.bound.spheres->edges[0][1] - arm.bound.spheres->edges[0][0]).norm(), std::hypot(0.5, 0.06), 1e-12);
  GeometryBound corners_only = arm.bound;
  auto without_edges = std::make_shared<SphereSet>(*arm.bound.spheres);
  without_edges->edges.clear();
  corners_only.spheres = without_edges;

  const Pose origin = Pose::Identity();
  const Pose tilted = translation(0.1, -0.2, 0.0) * Pose(Eigen::AngleAxisd(0.5, Vec(1, 1, 0).normalized()));
  for (const Pose& at : {origin, tilted}) {
    EXPECT_TRUE(fcl_collides(arm.fcl, at, board, origin));
    EXPECT_FALSE(touching(corners_only, at, board_bound, origin));  // no corner inside
    EXPECT_TRUE(touching(arm.bound, at, board_bound, origin));
    EXPECT_TRUE(touching(board_bound, origin, arm.bound, at));
  }
  // Beside the board, and across its edge 1 um short of it (no triangle deep enough): no proof.
  EXPECT_FALSE(touching(arm.bound, translation(0.6, 0, 0), board_bound, origin));
  EXPECT_FALSE(fcl_collides(arm.fcl, translation(0.6, 0, 0), board, origin));
  EXPECT_FALSE(touching(arm.bound, translation(0.53 - 1e-6, 0, 0), board_bound, origin));
  EXPECT_TRUE(touching(arm.bound, translation(0.53 - 1e-4, 0, 0), board_bound, origin));

  // A table leg through a mobile base's box, neither's corner inside the other: a box's edge.
  const GeometryBound base = box_bound(Vec(1.0, 0.6, 0.7)), leg = box_bound(Vec(0.05, 0.05, 1.5));
  const Pose yawed = translation(0.45, 0.25, 0.0) * Pose(Eigen::AngleAxisd(0.3, Vec::UnitZ()));
  EXPECT_TRUE(touching(base, origin, leg, yawed));
  EXPECT_TRUE(fcl_collides(std::make_shared<fcl::Boxd>(1.0, 0.6, 0.7), origin, std::make_shared<fcl::Boxd>(0.05, 0.05, 1.5),
                           yawed));
}

TEST(GeometryBounds, EdgeProofNeverWhereFclIsFree) {
  // Sliver triangles (one edge, the third corner 0.1 um outward) grazing a solid box, cylinder or
  // sphere: the edge tangent to the surface, within 20 um of it on either side, or through it at
  // a slant. Wherever the proof says touching, FCL must collide.
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(-1, 1), u01(0, 1);
  const std::vector<Solid> shapes = {
      {box_bound(Vec(0.4, 0.3, 0.025)), std::make_shared<fcl::Boxd>(0.4, 0.3, 0.025)},
      {box_bound(Vec(1.3, 0.05, 0.7)), std::make_shared<fcl::Boxd>(1.3, 0.05, 0.7)},
      {cylinder_bound(0.04, 0.6), std::make_shared<fcl::Cylinderd>(0.04, 0.6)},
      {cylinder_bound(0.3, 0.02), std::make_shared<fcl::Cylinderd>(0.3, 0.02)},
      {sphere_bound(0.07), std::make_shared<fcl::Sphered>(0.07)},
  };
  int proven = 0, fcl_only = 0, free = 0;
  for (int i = 0; i < 6000; ++i) {
    const Solid& s = shapes[i % shapes.size()];
    const auto [x, n] = surface_point(s.bound, rng);
    const double depth = 20e-6 * u(rng);  // > 0: inside
    Vec d = Vec(u(rng), u(rng), u(rng)).normalized();
    if (i % 4 != 0) d = (d - d.dot(n) * n + 1e-4 * u(rng) * n).normalized();  // tangent, or nearly
    const double length = 0.005 + 0.3 * u01(rng), at = u01(rng);
    const Vec mid = x - depth * n;
    const Vec a = mid - at * length * d, b = mid + (1 - at) * length * d;
    const Vec c = 0.5 * (a + b) + 1e-7 * n;
    // The triangle in its own frame; the primitive and the mesh at random poses.
    const Pose prim = random_pose(rng), mesh_pose = random_pose(rng);
    const Pose to_mesh = mesh_pose.inverse() * prim;
    const Mesh m = make_mesh({to_mesh * a, to_mesh * b, to_mesh * c}, {{0, 1, 2}});
    const bool proof = touching(m.bound, mesh_pose, s.bound, prim);
    const bool fcl = fcl_collides(m.fcl, mesh_pose, s.fcl, prim);
    EXPECT_TRUE(fcl || !proof) << "case " << i << " depth " << depth;
    proven += proof;
    fcl_only += fcl && !proof;
    free += !fcl;
  }
  // Both answers occur, and the proof misses only contacts within about the margin.
  EXPECT_GT(proven, 1500);
  EXPECT_GT(free, 1500);
  EXPECT_GT(fcl_only, 0);
}

TEST(GeometryBounds, BoxEdgeProofNeverWhereFclIsFree) {
  // Two boxes, or a box and a cylinder or sphere, at random turns just touching: one moved along
  // a random direction to about where contact starts (bisection on FCL), then 0-20 um either way.
  std::mt19937_64 rng(12);
  std::uniform_real_distribution<double> u(-1, 1), u01(0, 1);
  const GeometryBound box_a = box_bound(Vec(1.0, 0.6, 0.7));
  const auto fcl_a = std::make_shared<fcl::Boxd>(1.0, 0.6, 0.7);
  const std::vector<Solid> others = {
      {box_bound(Vec(0.05, 0.05, 0.75)), std::make_shared<fcl::Boxd>(0.05, 0.05, 0.75)},
      {box_bound(Vec(1.5, 1.1, 0.03)), std::make_shared<fcl::Boxd>(1.5, 1.1, 0.03)},
      {cylinder_bound(0.05, 0.4), std::make_shared<fcl::Cylinderd>(0.05, 0.4)},
      {sphere_bound(0.1), std::make_shared<fcl::Sphered>(0.1)},
  };
  int proven = 0, free = 0;
  for (int i = 0; i < 2000; ++i) {
    const Solid& s = others[i % others.size()];
    const Pose pa = random_pose(rng);
    Pose pb = random_pose(rng);
    if (i % 2) pb.linear() = pa.linear() * Eigen::AngleAxisd(M_PI * u(rng), Vec::UnitZ()).toRotationMatrix();  // level
    const Vec dir = Vec(u(rng), u(rng), u(rng)).normalized();
    double in = 0.0, out = 3.0;  // along dir from pa's centre: colliding at in, free at out
    auto at = [&](double t) {
      Pose p = pb;
      p.translation() = pa.translation() + t * dir;
      return p;
    };
    for (int k = 0; k < 60; ++k) {
      const double mid = 0.5 * (in + out);
      (fcl_collides(fcl_a, pa, s.fcl, at(mid)) ? in : out) = mid;
    }
    const Pose p = at(in + 20e-6 * u(rng));
    const bool proof = touching(box_a, pa, s.bound, p);
    const bool fcl = fcl_collides(fcl_a, pa, s.fcl, p);
    EXPECT_TRUE(fcl || !proof) << "case " << i;
    proven += proof;
    free += !fcl;
  }
  EXPECT_GT(proven, 300);
  EXPECT_GT(free, 300);
}
