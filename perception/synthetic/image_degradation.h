#pragma once
// Camera imperfections for synthetic frames: linear motion blur and Gaussian sensor noise.
#include <opencv2/core.hpp>

namespace demoplan::perception {

struct Degradation {
  double noise_sigma = 0.0;  // grey levels (0..255), per pixel and channel
  double blur_px = 0.0;      // length of the linear motion blur, pixels (0: none)
  double blur_angle = 0.0;   // rad, direction of the blur in the image
};

// In place; `rng` makes it deterministic.
void degrade(cv::Mat& bgr, const Degradation& d, cv::RNG& rng);

}  // namespace demoplan::perception
