#pragma once
// A part's colour against its surroundings: RGB histograms of the pixels just inside and just
// outside its silhouette, learnt from the frames tracked so far, giving each colour the
// probability that it belongs to the part (the segmentation model of region-based trackers).
#include <vector>

#include <opencv2/core.hpp>

namespace demoplan::perception {

class ColorHistograms {
public:
  static constexpr int kBits = 4;  // per channel: 16 levels, 4096 bins

  // Pixels seen inside and outside the silhouette in one frame.
  void add_foreground(const cv::Vec3b& bgr) { ++fg_new_[bin(bgr)], ++fg_count_; }
  void add_background(const cv::Vec3b& bgr) { ++bg_new_[bin(bgr)], ++bg_count_; }
  // Blends this frame's pixels into the model (the first call takes them as they are).
  void update(float foreground_rate = 0.1f, float background_rate = 0.2f);

  bool initialised() const { return initialised_; }
  // P(part | colour), in [0.001, 0.999]; 0.5 before the first update.
  float foreground_probability(const cv::Vec3b& bgr) const { return probability_[bin(bgr)]; }
  // The same by the colour's bin (what is computed from the probability may be kept per bin).
  float bin_probability(int bin) const { return probability_[bin]; }

  static constexpr int kBins = 1 << (3 * kBits);
  static int bin(const cv::Vec3b& c) {
    return (c[0] >> (8 - kBits)) << (2 * kBits) | (c[1] >> (8 - kBits)) << kBits | (c[2] >> (8 - kBits));
  }

private:
  std::vector<float> fg_ = std::vector<float>(kBins, 0.f), bg_ = std::vector<float>(kBins, 0.f);
  std::vector<float> fg_new_ = std::vector<float>(kBins, 0.f), bg_new_ = std::vector<float>(kBins, 0.f);
  std::vector<float> probability_ = std::vector<float>(kBins, 0.5f);
  float fg_count_ = 0.f, bg_count_ = 0.f;
  bool initialised_ = false;
};

}  // namespace demoplan::perception
