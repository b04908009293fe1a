#pragma once
// Our reader of OpenCV calibration files in YAML (as OpenCV's calibration sample and
// cv::FileStorage write them; ROS camera_info files too). It replaces cv::FileStorage for
// reading them because OpenCV 4.6's YAML parser never returns on some malformed files (a
// 62-byte one found by fuzz_camera_yaml): this reader makes one pass over at most 4 MiB.
//
// The subset read: an optional "%YAML:1.x" (or "%YAML 1.x") header and "---"; one block mapping
// of "key: value" lines at one indentation. A value is a plain or quoted scalar, a flow sequence
// "[ ... ]" (which may span lines), or a block mapping indented under its key, optionally tagged
// ("camera_matrix: !!opencv-matrix"). Keys not read below may hold anything indented under them.
// Read: image_width and image_height (positive integers); camera_matrix (or cameraMatrix, K) and
// distortion_coefficients (or dist_coeffs, distCoeffs, D), each a mapping {rows, cols, dt, data}
// whose data holds rows x cols numbers (dt is not looked at: the numbers are read as doubles).
#include <array>
#include <string>
#include <vector>

namespace demoplan::perception {

struct OpenCvCalibration {
  int image_width = 0, image_height = 0;
  std::array<double, 9> camera_matrix{};  // row-major 3 x 3
  std::vector<double> distortion;         // row-major; empty when the file has none
};

// Throws InputError naming the file and the key (one line) for anything outside the subset,
// a missing key, or a matrix of the wrong size; the numbers are not checked further here.
OpenCvCalibration read_calibration_yaml(const std::string& path);

}  // namespace demoplan::perception
