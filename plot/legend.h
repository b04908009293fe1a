#pragma once
// A legend: a coloured swatch and a name per entry, in one row (wrapping when it does not fit).
#include <QColor>
#include <QString>
#include <vector>

#include "plot/canvas.h"

namespace demoplan::plot {

struct LegendEntry {
  QString name;
  QColor color;
  bool line = false;  // a line sample (curves, dashed limits) instead of a filled swatch
  bool dashed = false;
};

// The height the legend needs in `width`.
double legend_height(const std::vector<LegendEntry>& entries, double width, double font_size = 12);
// Drawn centred in `area`'s width from its top.
void draw_legend(Canvas& canvas, const QRectF& area, const std::vector<LegendEntry>& entries, double font_size = 12);

}  // namespace demoplan::plot
