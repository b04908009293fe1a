#pragma once
// A synthetic calibration video: the printable ChArUco page (camera/charuco_board.h) seen by a
// camera of known intrinsics from many poses, one frame a pose, for testing the calibration
// (camera/charuco_calibration.h) against the truth. Headless and deterministic for a seed.
//
// Writes into the output folder: calibration.mp4, board.json (demoplan-charuco-board) and
// camera_truth.json (demoplan-camera: the intrinsics the frames were rendered with).
#include <atomic>
#include <functional>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "core/geometry/se3.h"
#include "perception/camera/camera_model.h"
#include "perception/camera/charuco_board.h"
#include "perception/synthetic/image_degradation.h"

namespace demoplan::perception {

// 1280x720, fx = fy = 1100, cx = 640, cy = 360, no distortion.
Camera board_video_truth_camera();

struct BoardVideoOptions {
  CharucoBoard board;                         // 7 x 5 squares of 30 mm, markers 22 mm, DICT_5X5_100
  Camera camera = board_video_truth_camera();  // the truth (distortion is rendered too)
  int views = 30;
  unsigned seed = 1;
  double noise_sigma = 0.0;  // grey levels
  double blur_px = 0.0;      // motion blur length, pixels
  double fps = 5.0;
  std::string fourcc = "mp4v";
  std::function<void(int done, int total)> progress;
  const std::atomic<bool>* cancel = nullptr;
};

// `count` poses of the board in the camera frame (camera_T_board, board frame as in
// charuco_board.h): 0.35-0.75 m away, tilted 10-50 degrees about a random axis in its plane,
// turned up to 25 degrees in it, wholly inside the image; deterministic for `seed`.
std::vector<Pose> board_view_poses(const CharucoBoard& board, const Camera& camera, int count, unsigned seed);

// Renders printed pages as `camera` sees them; the per-pixel rays are computed once.
class BoardViewRenderer {
public:
  BoardViewRenderer(const CharucoBoard& board, const Camera& camera);
  // One frame (BGR): the page at camera_T_board on a grey background, then `degradation`.
  cv::Mat render(const Pose& camera_T_board, const Degradation& degradation, cv::RNG& rng) const;

private:
  Camera camera_;
  PrintableBoard page_;
  cv::Mat rays_;  // CV_32FC2, per pixel of the 2x supersampled image: undistorted x/z, y/z
};

struct BoardVideoOutput {
  std::string video, board, camera_truth;
  int frames = 0;
  double seconds = 0.0;
  bool cancelled = false;  // then no file was written
};

BoardVideoOutput write_board_video(const BoardVideoOptions& options, const std::string& out_dir);

}  // namespace demoplan::perception
