#pragma once
// A heat map of scattered samples over a plane region: each sample a square coloured by its
// value (a sequential scale, shown in a colour bar), grey where it has none, with a tick showing
// its direction (a robot base's yaw). Metres on both axes at the same scale.
#include <QColor>
#include <QPointF>
#include <QString>
#include <cmath>
#include <vector>

#include "plot/canvas.h"

namespace demoplan::plot {

struct HeatSample {
  double x = 0, y = 0;
  double value = std::nan("");      // NaN: drawn grey (no value)
  double direction = std::nan("");  // rad; NaN: no tick
};

struct HeatMap {
  QString title, x_label, y_label;
  QString value_label;  // the colour bar's, with its unit
  QString grey_label;   // what grey means
  double x0 = 0, x1 = 1, y0 = 0, y1 = 1;  // the region
  double cell = 0.05;                     // a sample's square side, data units
  std::vector<HeatSample> samples;
  std::vector<QPointF> marked;  // ringed (the best)
  std::vector<QPointF> references;  // crossed (the published poses)
  std::vector<std::vector<QPointF>> outlines;  // closed polygons (the furniture from above)
  QString outlines_label;
  QString marked_label, references_label;
};

// Where the region lies in `area` (metres at one scale on both axes, room left for the colour
// bar): what draw_heat_map draws by, and what a view hit-tests clicks with.
struct HeatMapFrame {
  QRectF box;  // the region plus half a square around it, in pixels
  double x0 = 0, y0 = 0, pad = 0, scale = 1;
  double side = 3;  // a sample square's side, pixels
  QPointF to_pixel(double x, double y) const { return {box.left() + (x - x0 + pad) * scale, box.bottom() - (y - y0 + pad) * scale}; }
};
HeatMapFrame heat_map_frame(const QRectF& area, const HeatMap& map);
// The sample under `pixel` (the last drawn on top), -1 for none.
int heat_map_sample_at(const QRectF& area, const HeatMap& map, QPointF pixel);

// The colour of t in [0, 1] on a perceptually even dark-to-light scale (viridis).
QColor sequential_color(double t);

void draw_heat_map(Canvas& canvas, const QRectF& area, const HeatMap& map);

}  // namespace demoplan::plot
