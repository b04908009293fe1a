#include "plot/heat_map.h"

#include <algorithm>
#include <array>
#include <limits>

#include "plot/axis.h"
#include "plot/palette.h"

namespace demoplan::plot {

QColor sequential_color(double t) {
  // Viridis at nine stops, linearly interpolated.
  static constexpr std::array<std::array<int, 3>, 9> stops{{{68, 1, 84}, {71, 44, 122}, {59, 81, 139},
                                                            {44, 113, 142}, {33, 144, 141}, {39, 173, 129},
                                                            {92, 200, 99}, {170, 220, 50}, {253, 231, 37}}};
  if (!std::isfinite(t)) t = 0;
  t = std::clamp(t, 0.0, 1.0) * (stops.size() - 1);
  const size_t i = std::min(static_cast<size_t>(t), stops.size() - 2);
  const double f = t - static_cast<double>(i);
  auto mix = [&](int c) { return static_cast<int>(std::lround(stops[i][c] * (1 - f) + stops[i + 1][c] * f)); };
  return QColor(mix(0), mix(1), mix(2));
}

namespace {
const TextStyle kTitleStyle{.size = 12, .bold = true};
constexpr double kBarWidth = 110, kLeftWidth = 48, kBottomHeight = 36;
}  // namespace

HeatMapFrame heat_map_frame(const QRectF& area, const HeatMap& map) {
  // Room: title on top, colour bar and keys on the right, tick labels left and below.
  const double title_h = map.title.isEmpty() ? 0 : Canvas::textSize(map.title, kTitleStyle).height() + 8;
  const QRectF room(QPointF(area.left() + kLeftWidth, area.top() + title_h),
                    QPointF(area.right() - kBarWidth, area.bottom() - kBottomHeight));
  HeatMapFrame f;
  f.x0 = map.x0, f.y0 = map.y0, f.pad = map.cell / 2;
  const double dx = map.x1 - map.x0 + 2 * f.pad, dy = map.y1 - map.y0 + 2 * f.pad;
  f.scale = std::max(1e-9, std::min(room.width() / dx, room.height() / dy));
  f.box = QRectF(room.left(), room.top(), dx * f.scale, dy * f.scale);
  f.side = std::max(3.0, map.cell * f.scale);
  return f;
}

int heat_map_sample_at(const QRectF& area, const HeatMap& map, QPointF pixel) {
  const HeatMapFrame f = heat_map_frame(area, map);
  int found = -1;
  bool found_valued = false;
  for (size_t i = 0; i < map.samples.size(); ++i) {
    const QPointF c = f.to_pixel(map.samples[i].x, map.samples[i].y);
    if (std::abs(pixel.x() - c.x()) > f.side / 2 || std::abs(pixel.y() - c.y()) > f.side / 2) continue;
    const bool valued = std::isfinite(map.samples[i].value);  // drawn over the grey ones
    if (found < 0 || valued || !found_valued) found = static_cast<int>(i), found_valued = valued;
  }
  return found;
}

void draw_heat_map(Canvas& canvas, const QRectF& area, const HeatMap& map) {
  const TextStyle tick_y{.size = 9.5, .color = kAxisColor, .align = Qt::AlignRight | Qt::AlignVCenter};
  const TextStyle tick_x{.size = 9.5, .color = kAxisColor, .align = Qt::AlignHCenter | Qt::AlignTop};
  const TextStyle label{.size = 10, .color = kAxisColor, .align = Qt::AlignHCenter | Qt::AlignBottom};
  const QColor grey(0xc8, 0xc8, 0xc8);

  double v0 = std::numeric_limits<double>::infinity(), v1 = -v0;
  for (const auto& s : map.samples)
    if (std::isfinite(s.value)) v0 = std::min(v0, s.value), v1 = std::max(v1, s.value);
  const bool any_value = std::isfinite(v0);
  const Ticks vt = any_value ? nice_ticks(v0, v1, 5) : Ticks{};

  const HeatMapFrame frame = heat_map_frame(area, map);
  const QRectF& box = frame.box;
  const double pad = frame.pad;
  auto sx = [&](double x) { return frame.to_pixel(x, map.y0).x(); };
  auto sy = [&](double y) { return frame.to_pixel(map.x0, y).y(); };
  if (!map.title.isEmpty()) canvas.text({area.left(), area.top()}, map.title, kTitleStyle);

  canvas.fillRect(box, QColor(0xf6, 0xf6, 0xf6));
  const Ticks xt = nice_ticks(map.x0, map.x1, 6), yt = nice_ticks(map.y0, map.y1, 6);
  for (double v : xt.values) {
    if (v < map.x0 - pad - 1e-9 || v > map.x1 + pad + 1e-9) continue;
    canvas.line({sx(v), box.top()}, {sx(v), box.bottom()}, Stroke{kGridColor, 1});
    canvas.text({sx(v), box.bottom() + 4}, tick_label(v, xt.step), tick_x);
  }
  for (double v : yt.values) {
    if (v < map.y0 - pad - 1e-9 || v > map.y1 + pad + 1e-9) continue;
    canvas.line({box.left(), sy(v)}, {box.right(), sy(v)}, Stroke{kGridColor, 1});
    canvas.text({box.left() - 5, sy(v)}, tick_label(v, yt.step), tick_y);
  }
  canvas.text({box.center().x(), area.bottom()}, map.x_label, label);
  canvas.text({area.left() + 10, box.center().y()}, map.y_label,
              TextStyle{.size = 10, .color = kAxisColor, .align = Qt::AlignHCenter | Qt::AlignTop, .vertical = true});

  const double side = frame.side;
  auto color_of = [&](double v) { return sequential_color((v - vt.min) / std::max(vt.max - vt.min, 1e-12)); };
  canvas.beginGroup(QStringLiteral("samples"));
  // Grey first, so coloured samples stay visible where squares overlap.
  for (int pass = 0; pass < 2; ++pass)
    for (const auto& s : map.samples) {
      const bool valued = std::isfinite(s.value);
      if (valued != (pass == 1)) continue;
      const QPointF c(sx(s.x), sy(s.y));
      canvas.fillRect(QRectF(c.x() - side / 2, c.y() - side / 2, side, side), valued ? color_of(s.value) : grey);
      if (std::isfinite(s.direction)) {
        const double r = side * 0.45;
        canvas.line(c, c + QPointF(r * std::cos(s.direction), -r * std::sin(s.direction)),
                    Stroke{valued ? QColor(255, 255, 255, 200) : QColor(0x80, 0x80, 0x80), 1.2});
      }
    }
  canvas.endGroup();
  canvas.beginClip(box);
  const Stroke outline{QColor(0x33, 0x33, 0x33, 170), 1.5};
  for (const auto& polygon : map.outlines) {
    std::vector<QPointF> pixels;
    for (const QPointF& p : polygon) pixels.push_back(frame.to_pixel(p.x(), p.y()));
    if (!pixels.empty()) pixels.push_back(pixels.front());
    canvas.polyline(pixels, outline);
  }
  canvas.endClip();
  for (const QPointF& p : map.marked) {
    const QPointF c(sx(p.x()), sy(p.y()));
    canvas.strokeRect(QRectF(c.x() - side / 2 - 3, c.y() - side / 2 - 3, side + 6, side + 6), Stroke{Qt::black, 2});
  }
  auto cross = [&](QPointF c) {
    canvas.line(c + QPointF(-5, -5), c + QPointF(5, 5), Stroke{QColor(0xd0, 0x30, 0x30), 2});
    canvas.line(c + QPointF(-5, 5), c + QPointF(5, -5), Stroke{QColor(0xd0, 0x30, 0x30), 2});
  };
  for (const QPointF& p : map.references) cross({sx(p.x()), sy(p.y())});
  canvas.strokeRect(box, Stroke{QColor(0xaa, 0xaa, 0xaa), 1});

  // Colour bar, then the key to grey, the ring and the crosses.
  const double bx = box.right() + 22, bar_h = std::min(160.0, box.height() * 0.6);
  double y = box.top();
  if (any_value) {
    canvas.text({bx, y}, map.value_label, TextStyle{.size = 10, .color = kAxisColor});
    y += 18;
    const int steps = 40;
    for (int k = 0; k < steps; ++k)
      canvas.fillRect(QRectF(bx, y + bar_h * k / steps, 14, bar_h / steps + 0.5),
                      sequential_color(1.0 - (k + 0.5) / steps));
    for (double v : vt.values) {
      const double ty = y + bar_h * (1 - (v - vt.min) / std::max(vt.max - vt.min, 1e-12));
      canvas.line({bx + 14, ty}, {bx + 18, ty}, Stroke{kAxisColor, 1});
      canvas.text({bx + 21, ty}, tick_label(v, vt.step),
                  TextStyle{.size = 9.5, .color = kAxisColor, .align = Qt::AlignLeft | Qt::AlignVCenter});
    }
    y += bar_h + 16;
  }
  const TextStyle key{.size = 9.5, .color = kAxisColor, .align = Qt::AlignLeft | Qt::AlignVCenter};
  auto key_row = [&](const QString& text, auto&& swatch) {
    if (text.isEmpty()) return;
    swatch(QPointF(bx + 7, y + 7));
    canvas.text({bx + 20, y + 7}, text, key);
    y += 20;
  };
  key_row(map.grey_label, [&](QPointF c) { canvas.fillRect(QRectF(c.x() - 6, c.y() - 6, 12, 12), grey); });
  if (!map.marked.empty())
    key_row(map.marked_label, [&](QPointF c) { canvas.strokeRect(QRectF(c.x() - 6, c.y() - 6, 12, 12), Stroke{Qt::black, 2}); });
  if (!map.references.empty())
    key_row(map.references_label, cross);
  if (!map.outlines.empty())
    key_row(map.outlines_label, [&](QPointF c) { canvas.strokeRect(QRectF(c.x() - 6, c.y() - 6, 12, 12), outline); });
}

}  // namespace demoplan::plot
