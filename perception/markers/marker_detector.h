#pragma once
// Finding ArUco markers in a frame: ids and corner pixels, refined to sub-pixel accuracy.
#include <array>
#include <string>
#include <vector>

#include <opencv2/aruco.hpp>
#include <opencv2/core.hpp>

namespace demoplan::perception {

struct MarkerDetection {
  int id = 0;
  // Top-left, top-right, bottom-right, bottom-left corner of the black square as printed.
  std::array<cv::Point2f, 4> corners;
  bool edges_refined = false;  // all four edges were measured (a partly hidden marker fails)
};

struct MarkerDetectorOptions {
  // Corners from lines fitted to the marker's edges (edge_refinement.h), twice; where that fails,
  // and without it, OpenCV's CORNER_REFINE_SUBPIX. (SUBPIX first would hurt: on small markers
  // its window also sees the outer corner of the white margin and settles in between.)
  bool edge_refinement = true;
  // A 3x3 Gaussian on the image the candidates are searched in (not on the one the corners
  // are measured in): noise otherwise makes thousands of candidate contours.
  bool smooth_candidates = true;
  int threshold_window_min = 7;     // px, adaptive threshold windows (odd)
  int threshold_window_max = 23;
  int threshold_window_step = 8;
  double min_perimeter_rate = 0.02; // of the image's larger side: smallest marker looked for
};

class MarkerDetector {
public:
  explicit MarkerDetector(const std::string& dictionary, const MarkerDetectorOptions& options = {});
  // `image`: 8-bit BGR or grey.
  std::vector<MarkerDetection> detect(const cv::Mat& image) const;

private:
  bool edge_refinement_;
  bool smooth_;
  int cells_;  // marker side in cells, black border included
  cv::Ptr<cv::aruco::Dictionary> dictionary_;
  cv::Ptr<cv::aruco::DetectorParameters> parameters_;
};

}  // namespace demoplan::perception
