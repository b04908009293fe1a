#pragma once
// A grouped bar chart: groups along x (tasks), one bar per series in each group (planners),
// optional error bars, the value written above each bar where it fits.
#include <QColor>
#include <QString>
#include <cmath>
#include <optional>
#include <vector>

#include "plot/canvas.h"

namespace demoplan::plot {

struct Bar {
  double value = std::nan("");  // NaN: no bar (no data), drawn as a small "–"
  double low = std::nan(""), high = std::nan("");  // the error bar, when both are finite
};

struct BarChart {
  QString title;                         // above the plot area
  QString y_label;                       // with its unit
  std::vector<QString> groups;           // x categories
  std::vector<QString> series;           // bar names, coloured by series_color unless colors given
  std::vector<QColor> colors;            // optional, per series
  std::vector<std::vector<Bar>> bars;    // [group][series]
  std::optional<double> y_max;           // a fixed top (100 for percentages)
  int decimals = 1;                      // of the value labels
};

void draw_bar_chart(Canvas& canvas, const QRectF& area, const BarChart& chart);

}  // namespace demoplan::plot
