// Where a lost part may have been put down: the orientations the rest search tries; whether a
// rest stands on a support.
#include <gtest/gtest.h>

#include <limits>

#include <Eigen/Geometry>

#include "perception/render/render_mesh.h"
#include "perception/tracking/carrier_top.h"
#include "perception/tracking/support_search.h"

using namespace demoplan::perception;
using demoplan::Pose;

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

TEST(StandsOn, OnATraysTopLevelWithinTheToleranceAndOverIt) {
  // A tray 0.4 x 1.0 x 0.015 m, its centre at (0.5, 1.0, 0.7), turned 30 degrees about the vertical.
  Pose tray = Pose::Identity();
  tray.linear() = Eigen::AngleAxisd(M_PI / 6, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  tray.translation() << 0.5, 1.0, 0.7;
  const auto top = carrier_top(Eigen::AlignedBox3d(Eigen::Vector3d(-0.2, -0.5, -0.0075), Eigen::Vector3d(0.2, 0.5, 0.0075)), tray);
  ASSERT_TRUE(top);
  const SupportLevel level = support_level(*top);
  EXPECT_NEAR(level.height, 0.7075, 1e-12);
  EXPECT_TRUE(level.holds(Eigen::Vector2d(0.5, 1.0)));
  // Along its long side, 0.45 m from the centre: on it; across, 0.25 m: beside it.
  const Eigen::Vector2d along = tray.linear().col(1).head<2>(), across = tray.linear().col(0).head<2>();
  EXPECT_TRUE(level.holds(Eigen::Vector2d(0.5, 1.0) + 0.45 * along));
  EXPECT_FALSE(level.holds(Eigen::Vector2d(0.5, 1.0) + 0.25 * across));

  // A box 0.1 x 0.1 x 0.2 m (its centre at its frame's origin) standing on the tray.
  const RenderMesh box = box_mesh(Eigen::Vector3d(0.1, 0.1, 0.2), cv::Vec3f(1, 1, 1));
  const Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  auto at = [&](const Eigen::Vector3d& p, const Eigen::Matrix3d& R = Eigen::Matrix3d::Identity()) {
    Pose T = Pose::Identity();
    T.linear() = R;
    T.translation() = p;
    return T;
  };
  const double tolerance = 0.02, tilt = 10 * M_PI / 180;
  EXPECT_TRUE(stands_on({level}, box, centre, at({0.5, 1.0, 0.8075}), tolerance, tilt));
  EXPECT_TRUE(stands_on({level}, box, centre, at({0.5, 1.0, 0.8075 + 0.015}), tolerance, tilt)) << "1.5 cm above: within";
  EXPECT_FALSE(stands_on({level}, box, centre, at({0.5, 1.0, 0.8075 + 0.03}), tolerance, tilt)) << "floating 3 cm";
  EXPECT_FALSE(stands_on({level}, box, centre, at({0.5, 1.0, 0.8075 - 0.08}), tolerance, tilt)) << "sunk 8 cm";
  EXPECT_FALSE(stands_on({level}, box, centre, at(Eigen::Vector3d(0.5, 1.0, 0.8075) + 0.25 * tray.linear().col(0)), tolerance,
                         tilt))
      << "beside the tray, at its top's height";
  // Laid on its side (its lowest point 5 cm below its centre) and tilted.
  const Eigen::Matrix3d on_side = Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitX()).toRotationMatrix();
  EXPECT_TRUE(stands_on({level}, box, centre, at({0.5, 1.0, 0.7575}, on_side), tolerance, tilt));
  const Eigen::Matrix3d tilted = Eigen::AngleAxisd(18 * M_PI / 180, Eigen::Vector3d::UnitY()).toRotationMatrix();
  EXPECT_FALSE(stands_on({level}, box, centre, at({0.5, 1.0, 0.8075}, tilted), tolerance, tilt)) << "18 degrees off level";
  // No level: nothing to stand on.
  EXPECT_FALSE(stands_on({}, box, centre, at({0.5, 1.0, 0.8075}), tolerance, tilt));
  // How far it floats: its lowest point (10 cm below its centre standing, 5 cm on its side) over
  // the highest level under it it is not sunk into; over none, without end. (The mesh's vertices are
  // floats: within 1e-7 m.)
  EXPECT_NEAR(lowest_point_height(box, at({0.5, 1.0, 0.8075})), 0.7075, 1e-7);
  EXPECT_NEAR(lowest_point_height(box, at({0.5, 1.0, 0.7575}, on_side)), 0.7075, 1e-7);
  SupportLevel floor = level;
  floor.height = 0.0;
  EXPECT_NEAR(height_above_levels({floor, level}, box, centre, at({0.5, 1.0, 0.8075 + 0.12}), tolerance), 0.12, 1e-7);
  EXPECT_NEAR(height_above_levels({floor, level}, box, centre, at({0.5, 1.0, 0.8075 - 0.01}), tolerance), -0.01, 1e-7)
      << "sunk within the tolerance: on the tray";
  EXPECT_NEAR(height_above_levels({floor, level}, box, centre, at({0.5, 1.0, 0.8075 - 0.05}), tolerance), 0.6575, 1e-7)
      << "sunk 5 cm into the tray: over the floor";
  EXPECT_EQ(height_above_levels({level}, box, centre, at(Eigen::Vector3d(0.5, 1.0, 0.9) + 0.25 * tray.linear().col(0)), tolerance),
            std::numeric_limits<double>::infinity())
      << "beside the tray: over no level";
  // Stacked: on the top of the same box standing on the tray (the recheck counts the other
  // parts' tops as levels it may stand on).
  const auto box_top = carrier_top(Eigen::AlignedBox3d(Eigen::Vector3d(-0.05, -0.05, -0.1), Eigen::Vector3d(0.05, 0.05, 0.1)),
                                   at({0.5, 1.0, 0.8075}));
  ASSERT_TRUE(box_top);
  EXPECT_TRUE(stands_on({level, support_level(*box_top)}, box, centre, at({0.5, 1.0, 1.0075}), tolerance, tilt));
  EXPECT_FALSE(stands_on({level}, box, centre, at({0.5, 1.0, 1.0075}), tolerance, tilt));
}
