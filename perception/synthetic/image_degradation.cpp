#include "perception/synthetic/image_degradation.h"

#include <cmath>

#include <opencv2/imgproc.hpp>

namespace demoplan::perception {

cv::Vec3d lighting_at(int frame, int frames, double amplitude) {
  const double t = frames > 1 ? static_cast<double>(frame) / (frames - 1) : 0.0;
  const double brightness = 1.0 + amplitude * std::sin(2 * M_PI * 1.5 * t);
  const double warmth = 0.5 * amplitude * std::sin(2 * M_PI * 0.8 * t + 1.0);  // red up, blue down
  return {brightness * (1.0 - warmth), brightness, brightness * (1.0 + warmth)};
}

void degrade(cv::Mat& bgr, const Degradation& d, cv::RNG& rng) {
  if (d.light != cv::Vec3d(1.0, 1.0, 1.0)) cv::multiply(bgr, cv::Scalar(d.light[0], d.light[1], d.light[2]), bgr);
  if (d.blur_px >= 1.0) {
    const int n = static_cast<int>(std::ceil(d.blur_px)) | 1;  // odd kernel
    cv::Mat kernel = cv::Mat::zeros(n, n, CV_32F);
    const double c = (n - 1) / 2.0, h = d.blur_px / 2;
    const cv::Point2d a(c - h * std::cos(d.blur_angle), c - h * std::sin(d.blur_angle));
    const cv::Point2d b(c + h * std::cos(d.blur_angle), c + h * std::sin(d.blur_angle));
    cv::line(kernel, cv::Point(cvRound(a.x * 16), cvRound(a.y * 16)), cv::Point(cvRound(b.x * 16), cvRound(b.y * 16)),
             cv::Scalar(1.0), 1, cv::LINE_AA, 4);
    kernel /= cv::sum(kernel)[0];
    cv::filter2D(bgr, bgr, -1, kernel, cv::Point(-1, -1), 0, cv::BORDER_REPLICATE);
  }
  if (d.noise_sigma > 0) {
    cv::Mat noise(bgr.size(), CV_16SC3);
    rng.fill(noise, cv::RNG::NORMAL, 0, d.noise_sigma);
    cv::Mat wide;
    bgr.convertTo(wide, CV_16SC3);
    wide += noise;
    wide.convertTo(bgr, CV_8UC3);
  }
}

}  // namespace demoplan::perception
