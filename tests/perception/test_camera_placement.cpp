// Where a synthetic video's camera goes, and what it reports about the parts at rest: a part
// whose only marker faces up is seen from the chosen view in the open, and reported blind (with
// its points hidden) under a board that covers it from every view the placement tries; the synth
// command draws its random picks again on such a report.
#include <gtest/gtest.h>

#include "perception/synthetic/camera_placement.h"

using namespace demoplan;
using namespace demoplan::perception;

namespace {

// One 10 cm cube resting at the origin (its bottom on z = 0) for one frame, a 5 cm marker on its top face.
DemoScript cube_at_rest() {
  DemoScript s;
  s.frames = 1;
  s.object_ids = {"cube"};
  s.bounds = {Eigen::AlignedBox3d(Eigen::Vector3d(-0.05, -0.05, 0), Eigen::Vector3d(0.05, 0.05, 0.1))};
  s.poses = {{Pose::Identity()}};
  return s;
}

std::vector<std::vector<ObjectMarker>> top_marker() {
  ObjectMarker m;
  m.id = 7;
  m.size = 0.05;
  m.object_T_marker = Pose(Eigen::Translation3d(0, 0, 0.1));  // z: out of the top face
  return {{m}};
}

}  // namespace

TEST(CameraPlacement, APartInTheOpenIsSeenFromTheChosenView) {
  CameraPlacementReport report{-1, -1};
  const Camera c = place_camera(cube_at_rest(), {}, top_marker(), {}, &report);
  ASSERT_TRUE(c.world_T_camera);
  EXPECT_EQ(report.blind_rests, 0);
  EXPECT_EQ(report.hidden_points, 0);
  // The camera looks down at the marker from above its face's 70-degree cone.
  const Eigen::Vector3d to_eye = (c.world_T_camera->translation() - Eigen::Vector3d(0, 0, 0.1)).normalized();
  EXPECT_GT(to_eye.z(), 0.34);
}

TEST(CameraPlacement, APartUnderABoardIsReportedBlindFromEveryView) {
  // A shelf board 5 cm above the cube's top, 2 m wide: every tried elevation looks through it.
  const std::vector<Eigen::AlignedBox3d> board{
      Eigen::AlignedBox3d(Eigen::Vector3d(-1, -1, 0.15), Eigen::Vector3d(1, 1, 0.17))};
  CameraPlacementReport report;
  const Camera c = place_camera(cube_at_rest(), board, top_marker(), {}, &report);
  ASSERT_TRUE(c.world_T_camera);
  EXPECT_EQ(report.blind_rests, 1);
  EXPECT_EQ(report.hidden_points, 9);  // the centre and the 8 pulled-in corners
  // Without markers nothing can be blind; the hidden points are still counted.
  place_camera(cube_at_rest(), board, {}, {}, &report);
  EXPECT_EQ(report.blind_rests, 0);
  EXPECT_EQ(report.hidden_points, 9);
}
