// SRDF in the benchmark's HPP conventions: "x y z qw qx qy qz" positions, contact polygons.
#include <gtest/gtest.h>

#include "core/model/srdf.h"

using namespace demoplan;

static const std::string kData = DEMOPLAN_DATA_DIR;

TEST(Srdf, PandaGripperFrameIsScalarFirst) {
  const Srdf s = load_srdf(kData + "/robots/franka_panda/panda.srdf");
  ASSERT_EQ(s.grippers.size(), 1u);
  const GraspFrame& g = s.grippers[0];
  EXPECT_EQ(g.name, "gripper");
  EXPECT_EQ(g.link, "panda_hand");
  EXPECT_DOUBLE_EQ(g.clearance, 0.08);
  EXPECT_TRUE(g.pose.translation().isApprox(Eigen::Vector3d(0, 0, 0.12)));
  // gtamp README: columns x_g=(0,0,1), y_g=(1,0,0), z_g=(0,1,0) in the hand frame.
  Eigen::Matrix3d expected;
  expected << 0, 1, 0, 0, 0, 1, 1, 0, 0;
  EXPECT_NEAR((g.pose.linear() - expected).norm(), 0.0, 1e-12);
  EXPECT_EQ(s.disabled_collisions.size(), 12u);
  EXPECT_TRUE(s.collision_disabled("panda_rightfinger", "panda_leftfinger"));
  EXPECT_FALSE(s.collision_disabled("panda_link1", "panda_link3"));
}

TEST(Srdf, YcbvHandlesAndContactSurface) {
  const Srdf s = load_srdf(kData + "/objects/ycbv/srdf/obj_000002.srdf");
  EXPECT_EQ(s.handles.size(), 8u);
  const GraspFrame* h = s.handle("handleZpx");
  ASSERT_NE(h, nullptr);
  EXPECT_DOUBLE_EQ(h->clearance, 0.075);
  EXPECT_TRUE(h->pose.translation().isApprox(Eigen::Vector3d(0, 0, 0.06)));
  // q = (w=0.7071068, y=0.7071068): a +90 deg turn about y, so the approach axis x points to -z.
  EXPECT_NEAR((h->pose.linear().col(0) - Eigen::Vector3d(0, 0, -1)).norm(), 0.0, 1e-6);
  ASSERT_EQ(s.contacts.size(), 1u);
  EXPECT_EQ(s.contacts[0].points.size(), 8u);
  ASSERT_EQ(s.contacts[0].polygons.size(), 6u);
  const auto polys = s.contacts[0].polygon_vertices();
  EXPECT_TRUE(polys[0][0].isApprox(Eigen::Vector3d(0.036, -0.082, 0.107)));  // "4 3 2 1 0": point 3 first
}

TEST(Srdf, ShelfHasTopAndTwoInsidePolygons) {
  const Srdf s = load_srdf(kData + "/furniture/shelf_1_1_shelf.srdf");
  ASSERT_EQ(s.contacts.size(), 2u);
  EXPECT_EQ(s.contacts[0].name, "top_shelf_surface");
  EXPECT_EQ(s.contacts[0].link, "top_desk");
  EXPECT_EQ(s.contacts[1].polygons.size(), 2u);
  for (const auto& p : s.contacts[1].polygon_vertices())
    for (const auto& v : p) EXPECT_DOUBLE_EQ(v.z(), -0.355);
}

TEST(Srdf, KmrSurfaceOnTheRobot) {
  const Srdf s = load_srdf(kData + "/robots/kuka_kmr_iiwa/kuka_kmr_iiwa.srdf");
  ASSERT_EQ(s.contacts.size(), 1u);
  EXPECT_EQ(s.contacts[0].name, "kmr_surface");
  EXPECT_EQ(s.contacts[0].link, "kmr_link");
  EXPECT_EQ(s.contacts[0].polygons[0].size(), 4u);
}
