#include "perception/tracking/color_histograms.h"

#include <algorithm>

namespace demoplan::perception {

void ColorHistograms::update(float foreground_rate, float background_rate) {
  if (!initialised_ && (fg_count_ < 1.f || bg_count_ < 1.f)) return;  // the first needs both sides
  // A side without pixels this time keeps its model.
  const float rf = !initialised_ ? 1.f : fg_count_ < 1.f ? 0.f : foreground_rate;
  const float rb = !initialised_ ? 1.f : bg_count_ < 1.f ? 0.f : background_rate;
  fg_count_ = std::max(fg_count_, 1.f);
  bg_count_ = std::max(bg_count_, 1.f);
  for (int i = 0; i < kBins; ++i) {
    fg_[i] = (1.f - rf) * fg_[i] + rf * fg_new_[i] / fg_count_;
    bg_[i] = (1.f - rb) * bg_[i] + rb * bg_new_[i] / bg_count_;
    const float sum = fg_[i] + bg_[i];
    probability_[i] = sum > 1e-9f ? std::clamp(fg_[i] / sum, 0.001f, 0.999f) : 0.5f;
  }
  std::fill(fg_new_.begin(), fg_new_.end(), 0.f);
  std::fill(bg_new_.begin(), bg_new_.end(), 0.f);
  fg_count_ = bg_count_ = 0.f;
  initialised_ = true;
}

}  // namespace demoplan::perception
