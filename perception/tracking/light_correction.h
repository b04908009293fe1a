#pragma once
// The light of a scene drifts over a video (clouds, lamps, the camera's exposure and white
// balance) while colour models learnt in one frame expect that frame's light. A frame is brought
// back to a reference frame's light by one gain per channel: the median over a coarse grid of
// the reference's colour over the frame's, so what moved (a hand, the parts, an occluder) is
// outvoted by what stayed.
#include <opencv2/core.hpp>

namespace demoplan::perception {

struct LightReference {
  cv::Mat small;  // the reference frame at 1/8 scale, BGR
};

LightReference light_reference(const cv::Mat& bgr);

// The gains (B, G, R) that bring `bgr` to the reference's light; (1, 1, 1) when every one is
// within `tolerance` of 1 (a hand passing shifts the median a little too).
cv::Scalar light_gain(const LightReference& reference, const cv::Mat& bgr, double tolerance);

}  // namespace demoplan::perception
