// The top of a tray the parts ride on: the face of its box that looks up, whichever way the box
// lies, counter-clockwise from above; none when the tray is tilted.
#include <gtest/gtest.h>

#include <cmath>

#include "perception/tracking/carrier_top.h"

using namespace demoplan;
using namespace demoplan::perception;

namespace {

TEST(CarrierTop, TheFaceThatLooksUpWhicheverWayTheBoxLies) {
  const Eigen::AlignedBox3d tray(Eigen::Vector3d(-0.2, -0.15, -0.0075), Eigen::Vector3d(0.2, 0.15, 0.0075));
  Pose P = Pose::Identity();
  P.translation() = Eigen::Vector3d(1.0, 2.0, 0.7);
  auto check = [&](const Pose& pose, double height) {
    const auto top = carrier_top(tray, pose);
    ASSERT_TRUE(top);
    ASSERT_EQ(top->size(), 4u);
    for (const auto& p : *top) EXPECT_NEAR(p.z(), height, 1e-12);
    const Eigen::Vector3d normal = ((*top)[1] - (*top)[0]).cross((*top)[2] - (*top)[1]);
    EXPECT_GT(normal.z(), 0) << "counter-clockwise seen from above";
    EXPECT_NEAR(normal.norm(), 0.4 * 0.3, 1e-12) << "the 40 x 30 cm face, not a side";
  };
  check(P, 0.7075);
  Pose upside_down = P;
  upside_down.linear() = Eigen::AngleAxisd(M_PI, Eigen::Vector3d::UnitX()).toRotationMatrix();
  check(upside_down, 0.7075);
  Pose turned = P;
  turned.linear() = Eigen::AngleAxisd(0.7, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  check(turned, 0.7075);
  // Tilted 15 degrees: no level top (10 allowed by default).
  Pose tilted = P;
  tilted.linear() = Eigen::AngleAxisd(15.0 * M_PI / 180, Eigen::Vector3d::UnitY()).toRotationMatrix();
  EXPECT_FALSE(carrier_top(tray, tilted));
  EXPECT_TRUE(carrier_top(tray, tilted, 20.0 * M_PI / 180));
  // A tray given without thickness (a marker scene's box of height 0): its one face, up.
  const Eigen::AlignedBox3d flat(Eigen::Vector3d(-0.2, -0.15, 0.0), Eigen::Vector3d(0.2, 0.15, 0.0));
  for (const Pose& pose : {P, upside_down}) {
    const auto top = carrier_top(flat, pose);
    ASSERT_TRUE(top);
    for (const auto& p : *top) EXPECT_NEAR(p.z(), 0.7, 1e-12);
    EXPECT_GT((((*top)[1] - (*top)[0]).cross((*top)[2] - (*top)[1])).z(), 0);
  }
}

}  // namespace
