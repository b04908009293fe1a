#include "perception/tracking/light_correction.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include <opencv2/imgproc.hpp>

namespace demoplan::perception {

namespace {
cv::Mat eighth(const cv::Mat& bgr) {
  cv::Mat small;
  cv::resize(bgr, small, cv::Size(), 1.0 / 8, 1.0 / 8, cv::INTER_AREA);
  return small;
}
}  // namespace

LightReference light_reference(const cv::Mat& bgr) { return {eighth(bgr)}; }

cv::Scalar light_gain(const LightReference& reference, const cv::Mat& bgr, double tolerance) {
  const cv::Mat small = eighth(bgr);
  if (small.size() != reference.small.size() || small.type() != CV_8UC3) return {1, 1, 1};
  cv::Scalar gain(1, 1, 1);
  bool relit = false;
  std::vector<float> ratios;
  for (int c = 0; c < 3; ++c) {
    ratios.clear();
    for (int y = 0; y < small.rows; ++y)
      for (int x = 0; x < small.cols; ++x) {
        const int now = small.at<cv::Vec3b>(y, x)[c], then = reference.small.at<cv::Vec3b>(y, x)[c];
        // Dark values are too coarse for a ratio (a codec's step of one grey level is 3 % at
        // 30), saturated ones say nothing.
        if (now > 48 && then > 48 && now < 250 && then < 250) ratios.push_back(static_cast<float>(then) / now);
      }
    if (ratios.size() < 16) continue;
    std::nth_element(ratios.begin(), ratios.begin() + ratios.size() / 2, ratios.end());
    gain[c] = ratios[ratios.size() / 2];
    relit = relit || std::abs(gain[c] - 1.0) > tolerance;
  }
  return relit ? gain : cv::Scalar(1, 1, 1);
}

}  // namespace demoplan::perception
