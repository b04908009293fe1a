#pragma once
// A line plot over time: curves, horizontal limit lines (dashed) and shaded intervals (rests).
#include <QColor>
#include <QPointF>
#include <QString>
#include <vector>

#include "plot/canvas.h"

namespace demoplan::plot {

struct Curve {
  QString name;
  QColor color;
  std::vector<QPointF> points;  // (x, y) in data units, x increasing
};

struct LimitLine {
  double y = 0;
  QColor color;
};

struct Interval {
  double begin = 0, end = 0;  // x in data units; a zero-width one is drawn a few px wide
  QColor color;
};

struct LinePlot {
  QString title, x_label, y_label;
  std::vector<Curve> curves;
  std::vector<LimitLine> limits;
  std::vector<Interval> intervals;
  bool x_axis_labels = true;  // tick labels and title under the plot (off in stacked plots)
  double min_tick_width = 0;  // px kept for the y tick labels, so plots in a column line up
};

void draw_line_plot(Canvas& canvas, const QRectF& area, const LinePlot& plot);

}  // namespace demoplan::plot
