#pragma once
// Sub-pixel marker corners from the marker's four edges: the black square's border is found
// along many short profiles across each side (where the intensity crosses halfway between the
// black border and the white margin), a line is fitted to each side and the corners are the
// lines' intersections. Much less biased than refining the corners alone on small markers,
// where the corner window also sees the marker's inner bits.
#include <array>

#include <opencv2/core.hpp>

namespace demoplan::perception {

// `grey`: 8-bit image; `corners`: the detector's corners (clockwise from top-left), refined
// in place. Returns false (corners unchanged) when an edge could not be measured.
bool refine_corners_on_edges(const cv::Mat& grey, std::array<cv::Point2f, 4>& corners, int cells_with_border = 6);

}  // namespace demoplan::perception
