#include "perception/tracking/color_blobs.h"

#include <algorithm>

#include <opencv2/imgproc.hpp>

namespace demoplan::perception {

std::vector<ColorBlob> color_blobs(const cv::Mat& image, const ColorHistograms& colors, const OcclusionMap& occlusion,
                                   int part, double min_area, int scale) {
  std::vector<ColorBlob> blobs;
  if (image.empty() || image.type() != CV_8UC3 || !colors.initialised()) return blobs;
  scale = std::max(scale, 1);
  cv::Mat small;
  cv::resize(image, small, cv::Size(image.cols / scale, image.rows / scale), 0, 0, cv::INTER_AREA);
  cv::Mat probability(small.size(), CV_32F), mask(small.size(), CV_8U);
  for (int v = 0; v < small.rows; ++v)
    for (int u = 0; u < small.cols; ++u) {
      const double x = (u + 0.5) * scale, y = (v + 0.5) * scale;
      const int mu = static_cast<int>(x * occlusion.scale), mv = static_cast<int>(y * occlusion.scale);
      int label = 0;
      if (!occlusion.empty() && mu < occlusion.labels.cols && mv < occlusion.labels.rows) label = occlusion.labels.at<uchar>(mv, mu);
      const bool other_part = label != 0 && label != OcclusionMap::kFurniture && label != part + 1;
      const float p = colors.foreground_probability(small.at<cv::Vec3b>(v, u));
      probability.at<float>(v, u) = p;
      mask.at<uchar>(v, u) = !other_part && p > 0.5f ? 255 : 0;
    }
  // A pixel or two of the part's colours elsewhere (noise, an edge's blend) is no part.
  cv::morphologyEx(mask, mask, cv::MORPH_OPEN, cv::getStructuringElement(cv::MORPH_RECT, {3, 3}));
  cv::Mat labels, stats, centroids;
  const int count = cv::connectedComponentsWithStats(mask, labels, stats, centroids, 8, CV_32S);
  std::vector<double> sum(count, 0.0);
  for (int v = 0; v < labels.rows; ++v)
    for (int u = 0; u < labels.cols; ++u) sum[labels.at<int>(v, u)] += probability.at<float>(v, u);
  for (int i = 1; i < count; ++i) {
    const int pixels = stats.at<int>(i, cv::CC_STAT_AREA);
    const double area = static_cast<double>(pixels) * scale * scale;
    if (area < min_area) continue;
    blobs.push_back({Eigen::Vector2d((centroids.at<double>(i, 0) + 0.5) * scale - 0.5, (centroids.at<double>(i, 1) + 0.5) * scale - 0.5),
                     area, sum[i] / pixels});
  }
  std::sort(blobs.begin(), blobs.end(), [](const ColorBlob& a, const ColorBlob& b) { return a.area > b.area; });
  return blobs;
}

}  // namespace demoplan::perception
