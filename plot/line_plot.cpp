#include "plot/line_plot.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "plot/axis.h"
#include "plot/palette.h"

namespace demoplan::plot {

void draw_line_plot(Canvas& canvas, const QRectF& area, const LinePlot& plot) {
  const TextStyle title_style{.size = 11.5, .bold = true, .align = Qt::AlignLeft | Qt::AlignTop};
  const TextStyle tick_y{.size = 9.5, .color = kAxisColor, .align = Qt::AlignRight | Qt::AlignVCenter};
  const TextStyle tick_x{.size = 9.5, .color = kAxisColor, .align = Qt::AlignHCenter | Qt::AlignTop};

  double x0 = std::numeric_limits<double>::infinity(), x1 = -x0, y0 = x0, y1 = -x0;
  for (const Curve& c : plot.curves)
    for (const QPointF& p : c.points) {
      x0 = std::min(x0, p.x()), x1 = std::max(x1, p.x());
      y0 = std::min(y0, p.y()), y1 = std::max(y1, p.y());
    }
  // The limits are part of the picture: the reader compares the curve with them.
  for (const LimitLine& l : plot.limits)
    if (std::isfinite(l.y)) y0 = std::min(y0, l.y), y1 = std::max(y1, l.y);
  if (!std::isfinite(x0)) x0 = 0, x1 = 1;
  if (x1 <= x0) x1 = x0 + 1;
  // A little room above and below, so a limit or a peak is not hidden in the frame; the ticks
  // stay at round numbers inside.
  if (!std::isfinite(y0)) y0 = 0, y1 = 1;
  const double pad = std::max(0.05 * (y1 - y0), 1e-3 * std::max(1.0, std::abs(y1)));
  y0 -= pad, y1 += pad;
  Ticks yt = nice_ticks(y0, y1, 4);
  std::erase_if(yt.values, [&](double v) { return v < y0 - 1e-12 || v > y1 + 1e-12; });
  yt.min = y0, yt.max = y1;
  const Ticks xt = nice_ticks(x0, x1, 8);

  double tick_w = plot.min_tick_width;
  for (double v : yt.values) tick_w = std::max(tick_w, Canvas::textSize(tick_label(v, yt.step), tick_y).width());
  const double title_h = plot.title.isEmpty() ? 0 : Canvas::textSize(plot.title, title_style).height() + 4;
  const double bottom_h = plot.x_axis_labels ? 18 + (plot.x_label.isEmpty() ? 0 : 16) : 6;
  const QRectF box(QPointF(area.left() + tick_w + 10, area.top() + title_h + 4),
                   QPointF(area.right() - 8, area.bottom() - bottom_h));
  if (!plot.title.isEmpty()) canvas.text(QPointF(box.left(), area.top()), plot.title, title_style);
  auto sx = [&](double x) { return box.left() + (x - x0) / (x1 - x0) * box.width(); };
  auto sy = [&](double y) { return box.bottom() - (y - yt.min) / (yt.max - yt.min) * box.height(); };

  for (const Interval& iv : plot.intervals) {
    double a = sx(iv.begin), b = sx(iv.end);
    if (b - a < 4) a = (a + b) / 2 - 2, b = a + 4;
    canvas.fillRect(QRectF(QPointF(std::max(a, box.left()), box.top()), QPointF(std::min(b, box.right()), box.bottom())),
                    iv.color);
  }
  for (double v : yt.values) {
    const double y = sy(v);
    canvas.line({box.left(), y}, {box.right(), y}, Stroke{v == 0 ? QColor(0xbb, 0xbb, 0xbb) : kGridColor, 1});
    canvas.text({box.left() - 5, y}, tick_label(v, yt.step), tick_y);
  }
  for (double v : xt.values) {
    if (v < x0 - 1e-9 || v > x1 + 1e-9) continue;
    const double x = sx(v);
    canvas.line({x, box.bottom()}, {x, box.bottom() + 3}, Stroke{kAxisColor, 1});
    if (plot.x_axis_labels) canvas.text({x, box.bottom() + 4}, tick_label(v, xt.step), tick_x);
  }
  if (plot.x_axis_labels && !plot.x_label.isEmpty())
    canvas.text({box.center().x(), area.bottom()}, plot.x_label,
                TextStyle{.size = 10, .color = kAxisColor, .align = Qt::AlignHCenter | Qt::AlignBottom});

  canvas.beginClip(box.adjusted(-1, -1, 1, 1));
  for (const LimitLine& l : plot.limits)
    if (std::isfinite(l.y)) canvas.line({box.left(), sy(l.y)}, {box.right(), sy(l.y)}, Stroke{l.color, 1.2, true});
  for (const Curve& c : plot.curves) {
    std::vector<QPointF> pts;
    pts.reserve(c.points.size());
    for (const QPointF& p : c.points) pts.emplace_back(sx(p.x()), sy(p.y()));
    canvas.polyline(pts, Stroke{c.color, 1.6});
  }
  canvas.endClip();
  canvas.strokeRect(box, Stroke{QColor(0xaa, 0xaa, 0xaa), 1});
}

}  // namespace demoplan::plot
