#pragma once
// Camera imperfections for synthetic frames: a lighting change (brightness and colour of the
// light, slowly varying over the video), linear motion blur and Gaussian sensor noise.
#include <opencv2/core.hpp>

namespace demoplan::perception {

struct Degradation {
  double noise_sigma = 0.0;  // grey levels (0..255), per pixel and channel
  double blur_px = 0.0;      // length of the linear motion blur, pixels (0: none)
  double blur_angle = 0.0;   // rad, direction of the blur in the image
  cv::Vec3d light{1.0, 1.0, 1.0};  // this frame's gain per channel (B, G, R): 1 is the light as rendered
};

// The light of frame `frame` of `frames` when it varies by `amplitude` (0.3: brightness between
// 70 % and 130 %, over about one and a half slow cycles, its colour warmer and cooler by half as much).
cv::Vec3d lighting_at(int frame, int frames, double amplitude);

// In place (light, then blur, then noise); `rng` makes it deterministic.
void degrade(cv::Mat& bgr, const Degradation& d, cv::RNG& rng);

}  // namespace demoplan::perception
