#pragma once
// Axis ticks at round numbers (1, 2, 2.5, 5 x 10^k) and their labels.
#include <QString>
#include <vector>

namespace demoplan::plot {

struct Ticks {
  double min = 0, max = 1;     // the axis range, widened to whole ticks
  std::vector<double> values;  // from min to max
  double step = 1;
};

// About `target` ticks covering [lo, hi]; a zero-width range is widened around its value.
Ticks nice_ticks(double lo, double hi, int target = 5);
// The tick label with as many decimals as the step needs ("0.5", "10", "2.25").
QString tick_label(double value, double step);

}  // namespace demoplan::plot
