// Mesh-mesh contact proven by a remembered triangle pair (mesh_contact_witness.h): the proof must
// never say "touching" where FCL, as the checker calls it, finds two meshes apart, and it must
// fire where a crossing FCL found holds at a nearby pose.
#include <fcl/fcl.h>
#include <gtest/gtest.h>

#include <random>

#include "core/geometry/se3.h"
#include "core/scene/mesh_contact_witness.h"

using namespace demoplan;

namespace {

using Vec = Eigen::Vector3d;
using Triangle3 = std::array<Vec, 3>;
using Model = fcl::BVHModel<fcl::OBBRSSd>;

std::shared_ptr<Model> model(const std::vector<Vec>& v, const std::vector<fcl::Triangle>& t) {
  auto bvh = std::make_shared<Model>();
  bvh->beginModel(static_cast<int>(t.size()), static_cast<int>(v.size()));
  bvh->addSubModel(v, t);
  bvh->endModel();
  return bvh;
}

std::shared_ptr<Model> triangle_model(const Triangle3& t) {
  return model({t[0], t[1], t[2]}, {fcl::Triangle(0, 1, 2)});
}

// A square tube along z, open at the ends (8 triangles).
std::shared_ptr<Model> tube(double side, double length) {
  const double s = side / 2, h = length / 2;
  std::vector<Vec> v;
  for (double z : {-h, h})
    for (const auto& [x, y] : std::vector<std::pair<double, double>>{{-s, -s}, {s, -s}, {s, s}, {-s, s}}) v.emplace_back(x, y, z);
  std::vector<fcl::Triangle> t;
  for (int i = 0; i < 4; ++i) {
    const int j = (i + 1) % 4;
    t.emplace_back(i, j, j + 4);
    t.emplace_back(i, j + 4, i + 4);
  }
  return model(v, t);
}

bool fcl_collides(const fcl::CollisionObjectd& a, const fcl::CollisionObjectd& b, fcl::CollisionResultd* out = nullptr) {
  fcl::CollisionRequestd request;
  fcl::CollisionResultd result;
  const bool hit = fcl::collide(&a, &b, request, result) > 0;
  if (out) *out = result;
  return hit;
}

Pose pose(const Vec& axis, double angle, const Vec& t) {
  Pose p = Pose::Identity();
  p.linear() = Eigen::AngleAxisd(angle, axis.normalized()).toRotationMatrix();
  p.translation() = t;
  return p;
}

Triangle3 moved(const Triangle3& t, const Pose& p) { return {p * t[0], p * t[1], p * t[2]}; }

}  // namespace

TEST(TrianglesCertainlyCross, ACleanCrossingButNotAGrazeNorCoplanarTriangles) {
  const Triangle3 floor{Vec(-1, -1, 0), Vec(1, -1, 0), Vec(0, 1, 0)};
  const Triangle3 post{Vec(0, -0.2, -0.5), Vec(0, 0.2, -0.5), Vec(0, 0, 0.5)};
  EXPECT_TRUE(triangles_certainly_cross(floor, post));
  EXPECT_TRUE(triangles_certainly_cross(post, floor));
  // The post standing on the floor, its lowest corner 0.5 um below: FCL sees contact, the
  // proof (1 um margin) does not claim it.
  const Triangle3 standing = moved(post, pose(Vec::UnitZ(), 0, Vec(0, 0, 0.5 - 0.5e-6)));
  EXPECT_FALSE(triangles_certainly_cross(floor, standing));
  EXPECT_TRUE(triangles_certainly_cross(floor, moved(post, pose(Vec::UnitZ(), 0, Vec(0, 0, 0.5 - 5e-6)))));
  // Crossing the floor's plane outside the floor, and lying in the floor's plane.
  EXPECT_FALSE(triangles_certainly_cross(floor, moved(post, pose(Vec::UnitZ(), 0, Vec(3, 0, 0)))));
  const Triangle3 flat{Vec(0, 0, 0), Vec(2, 0, 0), Vec(0, 2, 0)};
  EXPECT_FALSE(triangles_certainly_cross(floor, flat));
  // A triangle of no area has no plane to be crossed, but its edge still crosses (and FCL's
  // test finds that contact as well).
  const Triangle3 needle{Vec(0, 0, -1), Vec(0, 0, 1), Vec(0, 0, 1)};
  const Triangle3 needle_above = moved(needle, pose(Vec::UnitZ(), 0, Vec(0, 0, 1.5)));
  EXPECT_TRUE(triangles_certainly_cross(floor, needle));
  EXPECT_FALSE(triangles_certainly_cross(floor, needle_above));
  const fcl::CollisionObjectd floor_object(triangle_model(floor), Pose::Identity());
  EXPECT_TRUE(fcl_collides(floor_object, fcl::CollisionObjectd(triangle_model(needle), Pose::Identity())));
}

TEST(TrianglesCertainlyCross, NeverWhereFclFindsTheTrianglesApart) {
  // Random triangle pairs bisected onto FCL's contact boundary (a translation along a random
  // direction), then moved by up to 20 um either way: where the proof says crossing, FCL's
  // triangle test as the checker runs it (two BVH models at poses) must say touching.
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-1, 1);
  auto random_triangle = [&](double size) {
    const Vec c(u(rng), u(rng), u(rng));
    Triangle3 t;
    for (auto& x : t) x = c + size * Vec(u(rng), u(rng), u(rng));
    if (rng() % 4 == 0) t[2] = t[0] + (t[1] - t[0]) * 0.5 + 1e-3 * Vec(u(rng), u(rng), u(rng));  // a sliver
    return t;
  };
  int proofs = 0, fcl_contacts = 0, pairs = 0;
  for (int i = 0; i < 3000; ++i) {
    const Triangle3 p = random_triangle(0.3), q0 = random_triangle(0.3);
    const auto mp = triangle_model(p), mq = triangle_model(q0);
    const fcl::CollisionObjectd op(mp, Pose::Identity());
    const Vec dir = Vec(u(rng), u(rng), u(rng)).normalized();
    // q crosses p at offset 0 (moved onto p's centroid), is far at offset 2.
    const Vec to_p = (p[0] + p[1] + p[2]) / 3 - (q0[0] + q0[1] + q0[2]) / 3;
    auto collides_at = [&](double s) {
      const fcl::CollisionObjectd oq(mq, pose(Vec::UnitZ(), 0, to_p + s * dir));
      return fcl_collides(op, oq);
    };
    if (!collides_at(0.0) || collides_at(2.0)) continue;
    double lo = 0.0, hi = 2.0;
    for (int k = 0; k < 60; ++k) {
      const double mid = 0.5 * (lo + hi);
      (collides_at(mid) ? lo : hi) = mid;
    }
    for (double shift : {-20e-6, -5e-6, -1e-6, 0.0, 1e-6, 5e-6, 20e-6, -2e-3}) {
      const Pose at = pose(Vec::UnitZ(), 0, to_p + (lo + shift) * dir);
      const fcl::CollisionObjectd oq(mq, at);
      const bool fcl_hit = fcl_collides(op, oq);
      const bool proof = triangles_certainly_cross(p, moved(q0, at));
      ++pairs;
      fcl_contacts += fcl_hit;
      proofs += proof;
      ASSERT_FALSE(proof && !fcl_hit) << "pair " << i << " shift " << shift;
    }
  }
  EXPECT_GT(pairs, 8000);
  // Not vacuous: the proof fires on a good share of the contacts (2 mm deep ones, mostly).
  EXPECT_GT(proofs, fcl_contacts / 10);
}

TEST(MeshContactWitnesses, ACrossingFclFoundProvesTheContactAtANearbyPoseOnly) {
  // Two tubes crossing at right angles through each other's middle.
  const auto arm = tube(0.06, 0.5), other = tube(0.06, 0.5);
  fcl::CollisionObjectd a(arm, Pose::Identity());
  fcl::CollisionObjectd b(other, pose(Vec::UnitX(), M_PI / 2, Vec(0.0, 0.0, 0.05)));
  MeshContactWitnesses witnesses;
  EXPECT_FALSE(witnesses.prove(a, b));  // nothing learnt yet
  fcl::CollisionResultd result;
  ASSERT_TRUE(fcl_collides(a, b, &result));
  ASSERT_GE(result.numContacts(), 1u);
  witnesses.learn(a, result.getContact(0).b1, b, result.getContact(0).b2);
  EXPECT_TRUE(witnesses.prove(a, b));

  // 1 cm along the tube and 2 degrees about it: still crossing, proven without FCL.
  b.setTransform(pose(Vec(1, 0.03, 0), M_PI / 2, Vec(0.0, 0.0, 0.06)));
  EXPECT_TRUE(fcl_collides(a, b));
  EXPECT_TRUE(witnesses.prove(a, b));
  // Moved off the arm: FCL finds them apart, and so no pair proves contact.
  b.setTransform(pose(Vec::UnitX(), M_PI / 2, Vec(0.2, 0.0, 0.05)));
  EXPECT_FALSE(fcl_collides(a, b));
  EXPECT_FALSE(witnesses.prove(a, b));
  // Out of the remembered pose's neighbourhood the pair is not tried, whatever it would say.
  b.setTransform(pose(Vec::UnitX(), M_PI / 2, Vec(0.0, 0.0, -0.2)));
  EXPECT_TRUE(fcl_collides(a, b));
  EXPECT_FALSE(witnesses.prove(a, b));
}

TEST(MeshContactWitnesses, AGrazingContactIsNotLearnt) {
  // A tube lying on a flat sheet, 0.5 um into it: FCL reports contact, no pair certainly crosses.
  const auto sheet = model({Vec(-1, -1, 0), Vec(1, -1, 0), Vec(1, 1, 0), Vec(-1, 1, 0)},
                           {fcl::Triangle(0, 1, 2), fcl::Triangle(0, 2, 3)});
  const auto arm = tube(0.06, 0.5);
  fcl::CollisionObjectd a(sheet, Pose::Identity());
  fcl::CollisionObjectd b(arm, pose(Vec::UnitX(), M_PI / 2, Vec(0.0, 0.0, 0.03 - 0.5e-6)));
  fcl::CollisionResultd result;
  ASSERT_TRUE(fcl_collides(a, b, &result));
  MeshContactWitnesses witnesses;
  witnesses.learn(a, result.getContact(0).b1, b, result.getContact(0).b2);
  EXPECT_FALSE(witnesses.prove(a, b));
}
