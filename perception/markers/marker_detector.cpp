#include "perception/markers/marker_detector.h"

#include <algorithm>

#include <opencv2/imgproc.hpp>

#include "perception/markers/edge_refinement.h"
#include "perception/markers/marker_dictionary.h"

namespace demoplan::perception {

MarkerDetector::MarkerDetector(const std::string& dictionary, const MarkerDetectorOptions& o)
    : edge_refinement_(o.edge_refinement),
      smooth_(o.smooth_candidates),
      dictionary_(marker_dictionary(dictionary)),
      parameters_(cv::aruco::DetectorParameters::create()) {
  cells_ = dictionary_->markerSize + 2;
  parameters_->cornerRefinementMethod = cv::aruco::CORNER_REFINE_NONE;
  parameters_->adaptiveThreshWinSizeMin = o.threshold_window_min;
  parameters_->adaptiveThreshWinSizeMax = o.threshold_window_max;
  parameters_->adaptiveThreshWinSizeStep = o.threshold_window_step;
  parameters_->minMarkerPerimeterRate = o.min_perimeter_rate;
}

std::vector<MarkerDetection> MarkerDetector::detect(const cv::Mat& image) const {
  cv::Mat grey;
  if (image.channels() == 3) cv::cvtColor(image, grey, cv::COLOR_BGR2GRAY);
  else grey = image;
  std::vector<std::vector<cv::Point2f>> corners;
  std::vector<int> ids;
  if (smooth_) {
    cv::Mat smooth;
    cv::GaussianBlur(grey, smooth, cv::Size(3, 3), 0);
    cv::aruco::detectMarkers(smooth, dictionary_, corners, ids, parameters_);
  } else {
    cv::aruco::detectMarkers(grey, dictionary_, corners, ids, parameters_);
  }
  std::vector<MarkerDetection> out(ids.size());
  for (size_t i = 0; i < ids.size(); ++i) {
    out[i].id = ids[i];
    for (int k = 0; k < 4; ++k) out[i].corners[k] = corners[i][k];
    if (edge_refinement_) {
      auto corners2 = out[i].corners;
      if (refine_corners_on_edges(grey, corners2, cells_) && refine_corners_on_edges(grey, corners2, cells_)) {
        out[i].corners = corners2;
        out[i].edges_refined = true;
        continue;
      }
    }
    // A window of about a third of a cell: larger ones reach the white margin's outer corner.
    double side = 1e9;
    for (int k = 0; k < 4; ++k) side = std::min(side, cv::norm(out[i].corners[(k + 1) % 4] - out[i].corners[k]));
    const int win = std::clamp(static_cast<int>(side / cells_ / 3), 1, 3);
    std::vector<cv::Point2f> c(out[i].corners.begin(), out[i].corners.end());
    cv::cornerSubPix(grey, c, cv::Size(win, win), cv::Size(-1, -1),
                     cv::TermCriteria(cv::TermCriteria::MAX_ITER | cv::TermCriteria::EPS, 30, 0.01));
    std::copy(c.begin(), c.end(), out[i].corners.begin());
  }
  return out;
}

}  // namespace demoplan::perception
