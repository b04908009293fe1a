// Where a lost part may have been put down: the orientations the rest search tries.
#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include "perception/tracking/support_search.h"

using namespace demoplan::perception;

namespace {

// The part's axis (its frame) that points down at world_R_part.
Eigen::Vector3d down_axis(const Eigen::Matrix3d& world_R_part) { return world_R_part.transpose() * -Eigen::Vector3d::UnitZ(); }

}  // namespace

TEST(LaidOnSides, AnUprightPartOnEachOfItsFourSides) {
  const Eigen::Matrix3d upright = Eigen::AngleAxisd(0.7, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  const std::vector<Eigen::Matrix3d> o = laid_on_sides(upright);
  ASSERT_EQ(o.size(), 4u);
  // The sides: +-x and +-y down once each, never z (as it stood, or upside down).
  std::vector<Eigen::Vector3d> sides;
  for (size_t i = 0; i < o.size(); ++i) {
    EXPECT_NEAR(o[i].determinant(), 1.0, 1e-12);
    EXPECT_TRUE((o[i].transpose() * o[i]).isIdentity(1e-12));
    const Eigen::Vector3d d = down_axis(o[i]);
    EXPECT_NEAR(std::abs(d.z()), 0.0, 1e-12) << "orientation " << i;
    EXPECT_NEAR(d.cwiseAbs().maxCoeff(), 1.0, 1e-12) << "orientation " << i;
    sides.push_back(d);
  }
  for (const Eigen::Vector3d& axis : std::vector<Eigen::Vector3d>{Eigen::Vector3d::UnitX(), -Eigen::Vector3d::UnitX(),
                                                                  Eigen::Vector3d::UnitY(), -Eigen::Vector3d::UnitY()})
    EXPECT_EQ(std::count_if(sides.begin(), sides.end(), [&](const Eigen::Vector3d& d) { return d.isApprox(axis); }), 1)
        << axis.transpose();
}

TEST(LaidOnSides, ABoxOnItsSideIsTriedStandingAndOnTheOtherSides) {
  // Lying on its +y face: +y points down.
  const Eigen::Matrix3d on_side = Eigen::AngleAxisd(-M_PI / 2, Eigen::Vector3d::UnitX()).toRotationMatrix();
  ASSERT_TRUE(down_axis(on_side).isApprox(Eigen::Vector3d::UnitY()));
  const std::vector<Eigen::Matrix3d> o = laid_on_sides(on_side);
  ASSERT_EQ(o.size(), 4u);
  bool standing = false, upside_down = false;
  for (size_t i = 0; i < o.size(); ++i) {
    const Eigen::Vector3d d = down_axis(o[i]);
    EXPECT_LT(std::abs(d.y()), 1e-12) << "tried on the side it lay on, or the opposite one";
    standing = standing || d.isApprox(-Eigen::Vector3d::UnitZ());
    upside_down = upside_down || d.isApprox(Eigen::Vector3d::UnitZ());
  }
  EXPECT_TRUE(standing);
  EXPECT_TRUE(upside_down);
}

TEST(StandingLevel, TheAxisNearestDownTurnedOntoItByTheSmallestRotation) {
  // Standing, yawed 40 degrees, its rest tracked 13 degrees off level.
  const Eigen::Matrix3d level = Eigen::AngleAxisd(0.7, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  const Eigen::Matrix3d tilted = Eigen::AngleAxisd(13 * M_PI / 180, Eigen::Vector3d(1, 2, 0).normalized()) * level;
  const Eigen::Matrix3d stood = standing_level(tilted);
  EXPECT_TRUE(down_axis(stood).isApprox(-Eigen::Vector3d::UnitZ(), 1e-12));
  EXPECT_NEAR(Eigen::AngleAxisd(stood.transpose() * tilted).angle(), 13 * M_PI / 180, 1e-9);
  EXPECT_NEAR(Eigen::AngleAxisd(stood.transpose() * level).angle(), 0.0, 1e-9) << "tilted about a horizontal axis: its yaw kept";
  // Laid on its +y side, 5 degrees off: +y straight down.
  const Eigen::Matrix3d on_side = Eigen::AngleAxisd(0.09, Eigen::Vector3d::UnitY()) *
                                  Eigen::AngleAxisd(-M_PI / 2, Eigen::Vector3d::UnitX()).toRotationMatrix();
  EXPECT_TRUE(down_axis(standing_level(on_side)).isApprox(Eigen::Vector3d::UnitY(), 1e-12));
  // Already level: unchanged.
  EXPECT_TRUE(standing_level(level).isApprox(level, 1e-12));
}
