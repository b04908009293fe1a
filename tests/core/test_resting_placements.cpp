// Where a part rests, from its mesh alone: boxes with known answers, a leaning block whose base
// cannot hold it, and a benchmark part against its hand-made SRDF contact surfaces.
#include <cmath>
#include <random>
#include <stdexcept>

#include <gtest/gtest.h>

#include "core/part/resting_placements.h"

namespace demoplan {
namespace {

std::vector<Eigen::Vector3d> box_points(const Eigen::Vector3d& size, int inside = 200) {
  std::vector<Eigen::Vector3d> pts;
  for (int i = 0; i < 8; ++i)
    pts.emplace_back((i & 1 ? 0.5 : -0.5) * size.x(), (i & 2 ? 0.5 : -0.5) * size.y(), (i & 4 ? 0.5 : -0.5) * size.z());
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-0.5, 0.5);
  for (int i = 0; i < inside; ++i) pts.emplace_back(u(rng) * size.x(), u(rng) * size.y(), u(rng) * size.z());
  return pts;
}

TEST(RestingPlacements, ABoxRestsOnItsSixFacesLargestMarginFirst) {
  const auto placements = resting_placements(box_points({0.1, 0.2, 0.3}), Eigen::Vector3d::Zero());
  ASSERT_EQ(placements.size(), 6u);
  // On a 0.2 x 0.3 face the centre lies 0.1 from the nearest edge and 0.05 above the face.
  for (int k = 0; k < 2; ++k) {
    EXPECT_NEAR(std::abs(placements[k].normal.x()), 1.0, 1e-9);
    EXPECT_NEAR(placements[k].margin, 0.1, 1e-9);
    EXPECT_NEAR(placements[k].height, 0.05, 1e-9);
    EXPECT_NEAR(placements[k].area, 0.06, 1e-9);
    EXPECT_NEAR(placements[k].tipping_angle, std::atan2(0.1, 0.05), 1e-9);
    EXPECT_EQ(placements[k].polygon.size(), 4u);
  }
  for (int k = 2; k < 6; ++k) EXPECT_NEAR(placements[k].margin, 0.05, 1e-9);
  // Resting on the plane: the face's corners at z = 0, the rest of the box above.
  for (const auto& p : placements) {
    for (const auto& c : p.polygon) EXPECT_NEAR((p.part_on_plane * c).z(), 0.0, 1e-9);
    for (const auto& c : box_points({0.1, 0.2, 0.3}, 0)) EXPECT_GE((p.part_on_plane * c).z(), -1e-9);
    EXPECT_NEAR((p.part_on_plane * Eigen::Vector3d::Zero()).z(), p.height, 1e-9);
  }
}

TEST(RestingPlacements, FacesTheCentreOfMassDoesNotProjectIntoAreNoPlacements) {
  // A block leaning over: its base [0, 1]^2 at z = 0, its top shifted by 2 along x. The centre
  // of mass (1.5, 0.5, 0.5) lies above neither the base nor the top.
  std::vector<Eigen::Vector3d> pts;
  for (int i = 0; i < 8; ++i) pts.emplace_back((i & 1) + (i & 4 ? 2.0 : 0.0), (i & 2) ? 1.0 : 0.0, (i & 4) ? 1.0 : 0.0);
  const auto placements = resting_placements(pts, {1.5, 0.5, 0.5});
  ASSERT_FALSE(placements.empty());
  for (const auto& p : placements) EXPECT_LT(std::abs(p.normal.z()), 0.99) << p.normal.transpose();
  // Off-centre mass makes a box's faces unequal: shifted 0.14 towards +z in a 0.3 tall box,
  // the box still stands on its ends but lies on its sides with 1 cm to spare.
  const auto shifted = resting_placements(box_points({0.1, 0.2, 0.3}), {0.0, 0.0, 0.14});
  for (const auto& p : shifted)
    if (std::abs(p.normal.z()) < 0.5) EXPECT_NEAR(p.margin, 0.01, 1e-9);
}

TEST(RestingPlacements, APartFromItsMeshMatchesItsSrdfContactFaces) {
  // YCB-V obj 2 (a box): the SRDF names its six faces at x = +-0.036, y = +-0.082, z = +-0.107.
  const auto mesh = load_mesh(std::string(DEMOPLAN_DATA_DIR) + "/objects/ycbv/meshes/obj_000002.obj");
  std::vector<Eigen::Vector3d> pts;
  for (const auto& v : mesh->vertices) pts.push_back(v.cast<double>() * 0.001);
  const Eigen::Vector3d com = centre_of_mass(*mesh, 0.001);
  EXPECT_LT(com.norm(), 0.01) << com.transpose();
  const auto placements = resting_placements(pts, com);
  ASSERT_FALSE(placements.empty());
  // The scanned box bulges: it touches a surface with part of each face only. Still it rests on
  // each of its six faces, the centre as far above as the SRDF's faces lie from it, and stands
  // best on a broad side.
  EXPECT_GT(std::abs(placements[0].normal.x()), std::cos(5 * M_PI / 180)) << placements[0].normal.transpose();
  EXPECT_GT(placements[0].margin, 0.04);
  const double half[3] = {0.036, 0.082, 0.107};
  for (int axis = 0; axis < 3; ++axis)
    for (double sign : {-1.0, 1.0}) {
      SCOPED_TRACE("axis " + std::to_string(axis) + " sign " + std::to_string(sign));
      const Eigen::Vector3d n = sign * Eigen::Vector3d::Unit(axis);
      const RestingPlacement* found = nullptr;
      for (const auto& p : placements)
        if (p.normal.dot(n) > std::cos(6 * M_PI / 180) && (!found || p.margin > found->margin)) found = &p;
      ASSERT_NE(found, nullptr);
      EXPECT_NEAR(found->height, half[axis], 0.005);
    }
}

TEST(RestingPlacements, PointsInAPlaneSpanNoVolume) {
  std::vector<Eigen::Vector3d> flat{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}, {0.5, 0.5, 0}};
  EXPECT_THROW(resting_placements(flat, Eigen::Vector3d::Zero()), std::invalid_argument);
  EXPECT_THROW(resting_placements({{0, 0, 0}, {1, 0, 0}}, Eigen::Vector3d::Zero()), std::invalid_argument);
}

}  // namespace
}  // namespace demoplan
