#pragma once
// A calibrated camera: pinhole intrinsics, OpenCV distortion and, when known, its pose in the
// world. Camera frame as in OpenCV: x right, y down, z along the optical axis.
//
// File "demoplan-camera" version 1 (JSON):
//   {"format": "demoplan-camera", "version": 1,
//    "image_size": [1280, 720],
//    "intrinsics": {"fx": 1100, "fy": 1100, "cx": 640, "cy": 360},
//    "distortion": [k1, k2, p1, p2, k3],             // OpenCV order; 0, 4, 5, 8, 12 or 14 values
//    "world_T_camera": {"t": [x, y, z], "q": [qx, qy, qz, qw]},   // optional
//    "board": {"dictionary": "DICT_4X4_100", "markers_x": 4, "markers_y": 3,
//              "marker_length": 0.08, "marker_separation": 0.02, "first_id": 80,
//              "world_T_board": {"t": ..., "q": ...}}}           // optional
// world_T_camera maps camera coordinates to world coordinates (metres). Without it the pose
// comes from the board, found in the video. OpenCV calibration files (.yaml, .yml, .xml with
// camera_matrix / distortion_coefficients / image_width / image_height, as the OpenCV
// calibration sample writes them) are read too; they carry intrinsics only, and are read by our
// own readers (calibration_yaml.h, calibration_xml.h), not by cv::FileStorage.
#include <optional>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "core/geometry/se3.h"
#include "perception/camera/marker_board.h"

namespace demoplan::perception {

struct Camera {
  cv::Size image_size{1280, 720};
  double fx = 1000, fy = 1000, cx = 640, cy = 360;
  std::vector<double> distortion;  // empty: none
  std::optional<Pose> world_T_camera;
  std::optional<MarkerBoard> board;

  cv::Matx33d camera_matrix() const { return {fx, 0, cx, 0, fy, cy, 0, 0, 1}; }
  cv::Mat distortion_coefficients() const;  // 1 x N CV_64F (N = 0 when none)
  // Projection of a point given in the camera frame, distortion applied.
  cv::Point2d project(const Eigen::Vector3d& p_camera) const;
};

// Reads either format (by extension: .json; .xml; else OpenCV calibration YAML). Throws InputError.
Camera load_camera(const std::string& path);
// Writes "demoplan-camera" version 1, atomically.
void save_camera(const std::string& path, const Camera& camera);

}  // namespace demoplan::perception
