#pragma once
// Median and mean of benchmark figures; NaN over no runs (printed as "-").
#include <algorithm>
#include <cmath>
#include <numeric>
#include <vector>

namespace demoplan::cli {

inline double median(std::vector<double> v) {
  if (v.empty()) return std::nan("");
  std::sort(v.begin(), v.end());
  return v.size() % 2 ? v[v.size() / 2] : 0.5 * (v[v.size() / 2 - 1] + v[v.size() / 2]);
}

inline double mean(const std::vector<double>& v) {
  return v.empty() ? std::nan("") : std::accumulate(v.begin(), v.end(), 0.0) / static_cast<double>(v.size());
}

}  // namespace demoplan::cli
