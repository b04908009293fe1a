#pragma once
// Where a part's colours show: the regions of a frame whose colours the part's model (its
// colour histograms, color_histograms.h) gives to the part more likely than not. A part carried
// out of the rest search's reach while lost (waiter_0 with the occluder: the cracker box, lost
// behind the pole in a fast carry, put down on the shelf's top 310 px from where it was last
// seen) is looked for where its colours show, wherever that is.
#include <vector>

#include <Eigen/Core>
#include <opencv2/core.hpp>

#include "perception/tracking/color_histograms.h"
#include "perception/tracking/region_pose.h"

namespace demoplan::perception {

struct ColorBlob {
  Eigen::Vector2d centre;  // image pixels
  double area = 0.0;       // image pixels
  double probability = 0.0;  // mean P(part) over it
};

// The blobs of `image` (BGR) whose pixels `colors` gives to the part with probability above 0.5,
// looked at every `scale` pixels, at least `min_area` image pixels large, largest first; pixels
// where `occlusion` has another part than `part` (which is tracked there) are no blob's.
std::vector<ColorBlob> color_blobs(const cv::Mat& image, const ColorHistograms& colors, const OcclusionMap& occlusion,
                                   int part, double min_area, int scale = 4);

}  // namespace demoplan::perception
