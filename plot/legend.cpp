#include "plot/legend.h"

namespace demoplan::plot {

namespace {

struct Placed {
  std::vector<std::vector<size_t>> rows;
  std::vector<double> widths;
};

double entry_width(const LegendEntry& e, const TextStyle& style) {
  return (e.line ? 24 : 14) + 6 + Canvas::textSize(e.name, style).width();
}

Placed place(const std::vector<LegendEntry>& entries, double width, const TextStyle& style) {
  const double gap = 22;
  Placed p;
  for (size_t i = 0; i < entries.size(); ++i) {
    const double w = entry_width(entries[i], style);
    if (p.rows.empty() || p.widths.back() + gap + w > width) {
      p.rows.emplace_back();
      p.widths.push_back(-gap);
    }
    p.rows.back().push_back(i);
    p.widths.back() += gap + w;
  }
  return p;
}

}  // namespace

double legend_height(const std::vector<LegendEntry>& entries, double width, double font_size) {
  const TextStyle style{.size = font_size};
  return static_cast<double>(place(entries, width, style).rows.size()) * font_size * 1.8;
}

void draw_legend(Canvas& canvas, const QRectF& area, const std::vector<LegendEntry>& entries, double font_size) {
  TextStyle style{.size = font_size, .align = Qt::AlignLeft | Qt::AlignVCenter};
  const Placed p = place(entries, area.width(), style);
  const double row_h = font_size * 1.8;
  for (size_t r = 0; r < p.rows.size(); ++r) {
    double x = area.center().x() - p.widths[r] / 2;
    const double y = area.top() + row_h * (static_cast<double>(r) + 0.5);
    for (size_t i : p.rows[r]) {
      const LegendEntry& e = entries[i];
      if (e.line) {
        canvas.line({x, y}, {x + 24, y}, Stroke{e.color, 2.0, e.dashed});
        x += 24;
      } else {
        canvas.fillRect(QRectF(x, y - 7, 14, 14), e.color);
        x += 14;
      }
      x += 6;
      canvas.text({x, y}, e.name, style);
      x += Canvas::textSize(e.name, style).width() + 22;
    }
  }
}

}  // namespace demoplan::plot
