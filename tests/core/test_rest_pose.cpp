// Snapping a resting part's estimate onto its support: levelled about its middle, so an
// estimate's tilt does not move it sideways; its face ends `gap` above the support.
#include <gtest/gtest.h>

#include <cmath>

#include "core/demo/rest_pose.h"

namespace demoplan {
namespace {

// The faces of a box of half-sizes (a, b, c) centred on its frame's origin, outward normals.
std::vector<std::vector<Eigen::Vector3d>> box_faces(double a, double b, double c) {
  using V = Eigen::Vector3d;
  return {{V(-a, -b, -c), V(-a, b, -c), V(a, b, -c), V(a, -b, -c)},    // bottom, normal -z
          {V(-a, -b, c), V(a, -b, c), V(a, b, c), V(-a, b, c)},        // top, +z
          {V(a, -b, -c), V(a, b, -c), V(a, b, c), V(a, -b, c)},        // +x
          {V(-a, -b, -c), V(-a, -b, c), V(-a, b, c), V(-a, b, -c)},    // -x
          {V(-a, b, -c), V(-a, b, c), V(a, b, c), V(a, b, -c)},        // +y
          {V(-a, -b, -c), V(a, -b, -c), V(a, -b, c), V(-a, -b, c)}};   // -y
}

TEST(RestPose, ATiltedEstimateIsLevelledAboutThePartsMiddle) {
  const double top = 0.75;
  const std::vector<std::vector<Eigen::Vector3d>> table{
      {{-1, -1, top}, {1, -1, top}, {1, 1, top}, {-1, 1, top}}};
  // A sugar box (9 x 4 x 17.5 cm) standing, estimated 11 degrees tilted and 3 mm high.
  Pose estimate = Pose::Identity();
  estimate.linear() = Eigen::AngleAxisd(11.0 * M_PI / 180, Eigen::Vector3d(1, 1, 0).normalized()).toRotationMatrix();
  estimate.translation() << 0.5, 0.2, top + 0.0875 + 0.003;
  const auto snapped = snap_to_support(box_faces(0.045, 0.02, 0.0875), estimate, table);
  ASSERT_TRUE(snapped);
  EXPECT_EQ(snapped->face, 0);
  EXPECT_NEAR(snapped->tilt, 11.0 * M_PI / 180, 1e-9);
  EXPECT_NEAR(snapped->pose.linear().col(2).z(), 1.0, 1e-12);  // standing up
  // Its middle stays where it was seen (about the bottom face it would move 17 mm sideways).
  EXPECT_NEAR((snapped->pose.translation() - estimate.translation()).head<2>().norm(), 0.0, 1e-9);
  EXPECT_NEAR(snapped->pose.translation().z(), top + 0.0875 + 0.001, 1e-9);  // 1 mm above the table
}

TEST(RestPose, SeenFromACameraTheDepthAlongItsLineOfSightIsCorrected) {
  const double top = 0.75;
  const std::vector<std::vector<Eigen::Vector3d>> table{
      {{-1, -1, top}, {1, -1, top}, {1, 1, top}, {-1, 1, top}}};
  const Eigen::Vector3d camera(-1.0, 0.2, 1.8);
  Pose truth = Pose::Identity();
  truth.translation() << 0.5, 0.2, top + 0.0875 + 0.001;
  // A monocular estimate 23 mm too far along the line of sight (shelf_2's YCBV_12 without markers).
  Pose estimate = truth;
  estimate.translation() += 0.023 * (truth.translation() - camera).normalized();
  SnapOptions options;
  options.viewpoint = camera;
  const auto seen = snap_to_support(box_faces(0.045, 0.02, 0.0875), estimate, table, options);
  ASSERT_TRUE(seen);
  EXPECT_NEAR((seen->pose.translation() - truth.translation()).norm(), 0.0, 1e-9);
  // Along the normal only the height is put right: 19 mm of the error stay.
  const auto plain = snap_to_support(box_faces(0.045, 0.02, 0.0875), estimate, table);
  ASSERT_TRUE(plain);
  EXPECT_GT((plain->pose.translation() - truth.translation()).norm(), 0.015);
}

TEST(RestPose, AnEstimateOverhangingTheEdgeIsSlidOnto) {
  const double top = 0.75;
  const std::vector<std::vector<Eigen::Vector3d>> table{
      {{-1, -1, top}, {1, -1, top}, {1, 1, top}, {-1, 1, top}}};
  Pose estimate = Pose::Identity();
  estimate.translation() << 1.03, 0.0, top + 0.0875;  // its bottom's centre 3 cm past the edge
  SnapOptions options;
  EXPECT_FALSE(snap_to_support(box_faces(0.045, 0.02, 0.0875), estimate, table, options));
  options.max_outside = 0.05;
  const auto snapped = snap_to_support(box_faces(0.045, 0.02, 0.0875), estimate, table, options);
  ASSERT_TRUE(snapped);
  EXPECT_NEAR(snapped->pose.translation().x(), 0.99, 1e-9);  // 1 cm inside the edge
  EXPECT_NEAR(snapped->slide, 0.04, 1e-9);
}

}  // namespace
}  // namespace demoplan
