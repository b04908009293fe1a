#pragma once
// Order statistics of a sample of figures (errors, residuals, timings, frame-to-frame steps): one
// definition for the evaluations, the event detectors' noise estimates and the benchmarks.
#include <algorithm>
#include <cstddef>
#include <vector>

namespace demoplan {

// The k-th smallest value (k from 0; past the last, the largest); `empty` when there is none.
inline double order_statistic(std::vector<double> v, size_t k, double empty = 0.0) {
  if (v.empty()) return empty;
  const auto kth = v.begin() + static_cast<long>(std::min(k, v.size() - 1));
  std::nth_element(v.begin(), kth, v.end());
  return *kth;
}

// The middle value, or the mean of the two middle values of an even count; `empty` when there is none.
inline double median(std::vector<double> v, double empty = 0.0) {
  if (v.empty()) return empty;
  const auto middle = v.begin() + static_cast<long>(v.size() / 2);
  std::nth_element(v.begin(), middle, v.end());
  // (Below the middle lies the lower half, its largest the value just below.)
  return v.size() % 2 ? *middle : 0.5 * (*std::max_element(v.begin(), middle) + *middle);
}

}  // namespace demoplan
