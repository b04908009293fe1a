#include "perception/tracking/track_error.h"

#include <cmath>
#include <vector>

#include "core/statistics.h"

namespace demoplan::perception {

TrackError track_error(const PoseTracks& estimated, const PoseTracks& truth) {
  TrackError out;
  std::vector<double> errors;
  for (size_t k = 0; k < truth.object_ids.size() && k < truth.samples.size(); ++k) {
    const int e = estimated.object_index(truth.object_ids[k]);
    for (size_t f = 0; f < truth.samples[k].size(); ++f) {
      const PoseSample& t = truth.samples[k][f];
      if (!t.valid) continue;
      ++out.truth_samples;
      if (e < 0 || f >= estimated.samples[e].size() || !estimated.samples[e][f].valid) continue;
      errors.push_back((estimated.samples[e][f].pose.translation() - t.pose.translation()).norm() * 1e3);
    }
  }
  out.estimated_samples = static_cast<int>(errors.size());
  out.coverage = out.truth_samples > 0 ? static_cast<double>(out.estimated_samples) / out.truth_samples : 0.0;
  if (errors.empty()) return out;
  out.median_translation_mm = median(errors);
  const auto rank = static_cast<size_t>(std::lround(0.95 * static_cast<double>(errors.size() - 1)));  // the nearest
  out.p95_translation_mm = order_statistic(std::move(errors), rank);
  return out;
}

}  // namespace demoplan::perception
