// Camera files (demoplan JSON, OpenCV YAML) and the camera pose from a board on the table.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "core/error.h"
#include "perception/camera/board_extrinsics.h"
#include "perception/camera/camera_model.h"
#include "perception/markers/marker_detector.h"
#include "perception/synthetic/marker_layout.h"
#include "perception/render/rasterizer.h"

namespace fs = std::filesystem;
using namespace demoplan;
using namespace demoplan::perception;

namespace {

class CameraTest : public ::testing::Test {
protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("demoplan_camera_" + std::to_string(::getpid()));
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string file(const std::string& name, const std::string& text) {
    const std::string p = (dir_ / name).string();
    std::ofstream(p) << text;
    return p;
  }
  fs::path dir_;
};

std::string error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

Pose look_down_at(const Eigen::Vector3d& eye, const Eigen::Vector3d& target) {
  const Eigen::Vector3d z = (target - eye).normalized(), x = z.cross(Eigen::Vector3d::UnitZ()).normalized();
  Pose T = Pose::Identity();
  T.linear() << x, z.cross(x), z;
  T.translation() = eye;
  return T;
}

}  // namespace

TEST_F(CameraTest, JsonRoundTrip) {
  Camera c;
  c.fx = 1000.5;
  c.fy = 1001.5;
  c.cx = 640.2;
  c.cy = 359.8;
  c.distortion = {0.1, -0.2, 0.001, 0.002, 0.05};
  c.world_T_camera = look_down_at({1, -1, 2}, {0, 0, 0.8});
  MarkerBoard b;
  b.world_T_board.translation() << 0.2, 0.1, 0.75;
  c.board = b;
  const std::string p = (dir_ / "camera.json").string();
  save_camera(p, c);
  const Camera r = load_camera(p);
  EXPECT_DOUBLE_EQ(r.fx, c.fx);
  EXPECT_DOUBLE_EQ(r.cy, c.cy);
  EXPECT_EQ(r.distortion, c.distortion);
  ASSERT_TRUE(r.world_T_camera && r.board);
  EXPECT_TRUE(r.world_T_camera->isApprox(*c.world_T_camera, 1e-9));
  EXPECT_EQ(r.board->first_id, b.first_id);
  EXPECT_TRUE(r.board->world_T_board.isApprox(b.world_T_board, 1e-9));
}

TEST_F(CameraTest, ReadsOpenCvCalibrationYaml) {
  const std::string p = file("calib.yaml",
                             "%YAML:1.0\n---\nimage_width: 1280\nimage_height: 720\n"
                             "camera_matrix: !!opencv-matrix\n   rows: 3\n   cols: 3\n   dt: d\n"
                             "   data: [ 900., 0., 640., 0., 910., 360., 0., 0., 1. ]\n"
                             "distortion_coefficients: !!opencv-matrix\n   rows: 1\n   cols: 5\n   dt: d\n"
                             "   data: [ 0.1, -0.05, 0., 0., 0.01 ]\n");
  const Camera c = load_camera(p);
  EXPECT_EQ(c.image_size, cv::Size(1280, 720));
  EXPECT_DOUBLE_EQ(c.fx, 900.0);
  EXPECT_DOUBLE_EQ(c.fy, 910.0);
  EXPECT_EQ(c.distortion.size(), 5u);
  EXPECT_FALSE(c.world_T_camera);
}

TEST_F(CameraTest, RejectsBadFiles) {
  EXPECT_NE(error_of([&] { load_camera(file("v2.json", R"({"format":"demoplan-camera","version":2})")); }).find("version"),
            std::string::npos);
  const std::string bad_dist = file("d.json", R"({"format":"demoplan-camera","version":1,"image_size":[640,480],
      "intrinsics":{"fx":500,"fy":500,"cx":320,"cy":240},"distortion":[0.1,0.2,0.3]})");
  EXPECT_NE(error_of([&] { load_camera(bad_dist); }).find("distortion"), std::string::npos);
  const std::string bad_q = file("q.json", R"({"format":"demoplan-camera","version":1,"image_size":[640,480],
      "intrinsics":{"fx":500,"fy":500,"cx":320,"cy":240},"world_T_camera":{"t":[0,0,1],"q":[0,0,0,0]}})");
  EXPECT_NE(error_of([&] { load_camera(bad_q); }).find("world_T_camera.q"), std::string::npos);
  EXPECT_NE(error_of([&] { load_camera(file("k.yaml", "%YAML:1.0\n---\nimage_width: 10\n")); }).find("camera_matrix"),
            std::string::npos);
}

TEST(BoardExtrinsics, RecoversTheCameraPose) {
  MarkerBoard board;
  board.markers_x = 3;
  board.markers_y = 2;
  board.marker_length = 0.07;
  board.marker_separation = 0.015;
  board.first_id = 90;
  // Face up on a table at z = 0.75 (the board's z points into the table).
  board.world_T_board = Pose(Eigen::AngleAxisd(M_PI, Eigen::Vector3d::UnitX()));
  board.world_T_board.translation() << 0.1, 0.3, 0.75;
  Camera cam;
  cam.fx = cam.fy = 1100;
  cam.cx = 639.5;
  cam.cy = 359.5;
  const Pose truth = look_down_at({0.9, -0.4, 1.6}, {0.2, 0.2, 0.75});
  Rasterizer r(cam.image_size, cam.fx, cam.fy, cam.cx, cam.cy, truth);
  r.clear({120, 110, 100}, {90, 80, 70});
  const auto grid = board.make();
  for (size_t i = 0; i < grid->objPoints.size(); ++i) {
    const auto& c = grid->objPoints[i];
    const Eigen::Vector3d p0(c[0].x, c[0].y, 0), p1(c[1].x, c[1].y, 0), p3(c[3].x, c[3].y, 0);
    Pose M = Pose::Identity();
    const Eigen::Vector3d x = (p1 - p0).normalized(), y = (p0 - p3).normalized();
    M.linear() << x, y, x.cross(y);
    M.translation() = (p0 + p1 + Eigen::Vector3d(c[2].x, c[2].y, 0) + p3) / 4;
    r.draw_marker(marker_image(board.dictionary, grid->ids[i]), printed_marker_side(board.dictionary, board.marker_length),
                  board.world_T_board * M);
  }
  const MarkerDetector detector(board.dictionary);
  const auto pose = camera_pose_from_board(board, cam, detector.detect(r.color()));
  ASSERT_TRUE(pose);
  EXPECT_EQ(pose->markers, 6);
  EXPECT_LT((pose->world_T_camera.translation() - truth.translation()).norm(), 0.005);
  EXPECT_LT(Eigen::AngleAxisd(pose->world_T_camera.linear().transpose() * truth.linear()).angle(), 0.005);
}
