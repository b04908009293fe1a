#pragma once
// Median and mean of benchmark figures; NaN over no runs (printed as "-").
#include <algorithm>
#include <cmath>
#include <numeric>
#include <vector>

#include "core/statistics.h"

namespace demoplan::cli {

inline double median(std::vector<double> v) { return demoplan::median(std::move(v), std::nan("")); }

inline double mean(const std::vector<double>& v) {
  return v.empty() ? std::nan("") : std::accumulate(v.begin(), v.end(), 0.0) / static_cast<double>(v.size());
}

}  // namespace demoplan::cli
