// Marker corners, the square-marker solver and the marker scene file.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "core/error.h"
#include "perception/markers/marker_detector.h"
#include "perception/markers/marker_scene.h"
#include "perception/synthetic/marker_layout.h"
#include "perception/render/rasterizer.h"
#include "perception/tracking/marker_pose.h"

namespace fs = std::filesystem;
using namespace demoplan;
using namespace demoplan::perception;

namespace {

Camera test_camera() {
  Camera c;
  c.fx = c.fy = 1100;
  c.cx = 639.5;
  c.cy = 359.5;
  return c;
}

}  // namespace

TEST(MarkerDetector, EdgeRefinedCornersAreSubPixel) {
  const Camera cam = test_camera();
  double worst = 0, sum = 0;
  int n = 0;
  for (int trial = 0; trial < 12; ++trial) {
    Rasterizer r(cam.image_size, cam.fx, cam.fy, cam.cx, cam.cy, Pose::Identity());
    r.clear({120, 120, 120}, {120, 120, 120});
    Pose M = Pose::Identity();
    M.translation() << -0.2 + 0.04 * trial, 0.05, 1.2 + 0.05 * trial;
    M.linear() = (Eigen::AngleAxisd(M_PI, Eigen::Vector3d::UnitX()) *
                  Eigen::AngleAxisd(0.2 + 0.07 * trial, Eigen::Vector3d(1, 1, 0).normalized()) *
                  Eigen::AngleAxisd(0.4 * trial, Eigen::Vector3d::UnitZ()))
                     .toRotationMatrix();
    const double size = 0.05;
    r.draw_marker(marker_image("DICT_4X4_100", 7), printed_marker_side("DICT_4X4_100", size), M);
    const auto found = MarkerDetector("DICT_4X4_100").detect(r.color());
    ASSERT_EQ(found.size(), 1u) << "trial " << trial;
    EXPECT_EQ(found[0].id, 7);
    EXPECT_TRUE(found[0].edges_refined);
    const auto pts = marker_corner_points(size);
    for (int c = 0; c < 4; ++c) {
      const cv::Point2d q = cam.project(M * Eigen::Vector3d(pts[c].x, pts[c].y, 0));
      const double e = cv::norm(cv::Point2d(found[0].corners[c]) - q);
      worst = std::max(worst, e);
      sum += e, ++n;
    }
    const auto cands = marker_pose_candidates(found[0], size, cam);
    ASSERT_FALSE(cands.empty());
    // The best or the flipped solution is the true one.
    double best = 1e9;
    for (const auto& c : cands) best = std::min(best, (c.camera_T_marker.translation() - M.translation()).norm());
    EXPECT_LT(best, 0.012) << "trial " << trial;
  }
  EXPECT_LT(sum / n, 0.1);
  EXPECT_LT(worst, 0.35);
}

TEST(MarkerScene, RoundTripAndErrors) {
  const fs::path dir = fs::temp_directory_path() / ("demoplan_markers_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  MarkerScene s;
  s.task = "shelf_0";
  s.objects.push_back({"YCBV_02", true, box_face_markers(Eigen::AlignedBox3d(Eigen::Vector3d(-0.04, -0.08, -0.1),
                                                                              Eigen::Vector3d(0.04, 0.08, 0.1)), 0), std::nullopt});
  const std::string p = (dir / "scene.json").string();
  save_marker_scene(p, s);
  const MarkerScene r = load_marker_scene(p);
  ASSERT_EQ(r.objects.size(), 1u);
  ASSERT_EQ(r.objects[0].markers.size(), 6u);
  int o = -1, m = -1;
  EXPECT_TRUE(r.find_marker(4, o, m));
  EXPECT_EQ(m, 4);
  EXPECT_TRUE(r.objects[0].markers[4].object_T_marker.isApprox(s.objects[0].markers[4].object_T_marker, 1e-9));
  EXPECT_FALSE(r.objects[0].box);
  // A part given by its box (a tray): its size and colour kept, its extent the box.
  s.objects.push_back({"TRAY", false, {}, Eigen::Vector3d(0.4, 0.3, 0.015), Eigen::Vector3i(120, 90, 60)});
  save_marker_scene(p, s);
  const MarkerScene t = load_marker_scene(p);
  ASSERT_EQ(t.objects.size(), 2u);
  ASSERT_TRUE(t.objects[1].box);
  EXPECT_TRUE(t.objects[1].box->isApprox(Eigen::Vector3d(0.4, 0.3, 0.015)));
  EXPECT_EQ(t.objects[1].box_rgb, Eigen::Vector3i(120, 90, 60));
  EXPECT_FALSE(t.objects[1].planning);
  EXPECT_TRUE(marker_extent(t.objects[1]).max().isApprox(Eigen::Vector3d(0.2, 0.15, 0.0075)));
  std::ofstream(dir / "flat.json") << R"({"format":"demoplan-marker-scene","version":1,"dictionary":"DICT_4X4_100",
    "objects":[{"id":"TRAY","markers":[],"box":{"size":[0.4,0.3,0]}}]})";
  try {
    load_marker_scene((dir / "flat.json").string());
    FAIL() << "a box without thickness accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("objects[0].box.size"), std::string::npos) << e.what();
  }
  // A marker id used twice is bad input naming the field.
  std::ofstream(dir / "dup.json") << R"({"format":"demoplan-marker-scene","version":1,"dictionary":"DICT_4X4_100",
    "objects":[{"id":"A","markers":[{"id":3,"size":0.05,"object_T_marker":{"t":[0,0,0],"q":[0,0,0,1]}}]},
               {"id":"B","markers":[{"id":3,"size":0.05,"object_T_marker":{"t":[0,0,0],"q":[0,0,0,1]}}]}]})";
  try {
    load_marker_scene((dir / "dup.json").string());
    FAIL() << "duplicate marker id accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("objects[1].markers[0].id"), std::string::npos) << e.what();
  }
  fs::remove_all(dir);
}
