#include "plot/bar_chart.h"

#include <algorithm>

#include "plot/axis.h"
#include "plot/palette.h"

namespace demoplan::plot {

void draw_bar_chart(Canvas& canvas, const QRectF& area, const BarChart& chart) {
  const TextStyle title_style{.size = 13, .bold = true, .align = Qt::AlignLeft | Qt::AlignTop};
  const TextStyle tick_style{.size = 10.5, .color = kAxisColor, .align = Qt::AlignRight | Qt::AlignVCenter};
  const TextStyle label_style{.size = 10.5, .color = kAxisColor, .align = Qt::AlignHCenter | Qt::AlignBottom,
                              .vertical = true};
  const TextStyle group_style{.size = 10.5, .color = QColor(0x33, 0x33, 0x33), .align = Qt::AlignHCenter | Qt::AlignTop};
  TextStyle value_style{.size = 9, .color = QColor(0x33, 0x33, 0x33), .align = Qt::AlignHCenter | Qt::AlignBottom};

  double top = 0;
  for (const auto& g : chart.bars)
    for (const Bar& b : g) {
      if (std::isfinite(b.value)) top = std::max(top, b.value);
      if (std::isfinite(b.high)) top = std::max(top, b.high);
    }
  Ticks ticks = nice_ticks(0, chart.y_max ? *chart.y_max : (top > 0 ? top * 1.12 : 1.0), 4);
  if (chart.y_max) ticks.max = *chart.y_max;

  double tick_w = 0;
  for (double v : ticks.values) tick_w = std::max(tick_w, Canvas::textSize(tick_label(v, ticks.step), tick_style).width());
  const double title_h = Canvas::textSize(chart.title, title_style).height() + 8;
  const QRectF plot(area.left() + 20 + tick_w + 6, area.top() + title_h + 14, 0, 0);
  const QRectF box(plot.topLeft(), QPointF(area.right() - 6, area.bottom() - 22));
  canvas.text(QPointF(box.left(), area.top()), chart.title, title_style);
  auto y_of = [&](double v) { return box.bottom() - (v - ticks.min) / (ticks.max - ticks.min) * box.height(); };

  // Light horizontal grid under everything, the axis on the left and at zero.
  for (double v : ticks.values) {
    const double y = y_of(v);
    if (v > ticks.min) canvas.line({box.left(), y}, {box.right(), y}, Stroke{kGridColor, 1});
    canvas.line({box.left() - 4, y}, {box.left(), y}, Stroke{kAxisColor, 1});
    canvas.text({box.left() - 7, y}, tick_label(v, ticks.step), tick_style);
  }
  canvas.text({area.left() + 2, box.center().y()}, chart.y_label,
              TextStyle{label_style.size, false, kAxisColor, Qt::AlignHCenter | Qt::AlignTop, true});

  const size_t groups = std::max<size_t>(1, chart.groups.size());
  const size_t series = std::max<size_t>(1, chart.series.size());
  const double slot = box.width() / static_cast<double>(groups);
  const double bar_w = std::min(34.0, slot * 0.8 / static_cast<double>(series));
  for (size_t g = 0; g < chart.groups.size(); ++g) {
    const double cx = box.left() + slot * (static_cast<double>(g) + 0.5);
    canvas.text({cx, box.bottom() + 5}, chart.groups[g], group_style);
    struct Label {
      QRectF box;  // where the value's text would go
      QString text;
    };
    std::vector<Label> labels;
    for (size_t s = 0; s < chart.series.size(); ++s) {
      const Bar b = g < chart.bars.size() && s < chart.bars[g].size() ? chart.bars[g][s] : Bar{};
      const double x = cx - bar_w * static_cast<double>(series) / 2 + bar_w * static_cast<double>(s);
      const QRectF slot_rect(x + 1, box.top(), bar_w - 2, box.height());
      if (!std::isfinite(b.value)) {
        canvas.text({slot_rect.center().x(), box.bottom() - 2}, QStringLiteral("–"),
                    TextStyle{9, false, QColor(0x99, 0x99, 0x99), Qt::AlignHCenter | Qt::AlignBottom});
        continue;
      }
      const QColor color = s < chart.colors.size() ? chart.colors[s] : series_color(chart.series[s]);
      const double y = y_of(std::clamp(b.value, ticks.min, ticks.max));
      canvas.fillRect(QRectF(QPointF(slot_rect.left(), y), QPointF(slot_rect.right(), box.bottom())), color);
      double label_y = y;
      if (std::isfinite(b.low) && std::isfinite(b.high)) {
        const double y_lo = y_of(std::clamp(b.low, ticks.min, ticks.max));
        const double y_hi = y_of(std::clamp(b.high, ticks.min, ticks.max));
        const Stroke whisker{QColor(0x22, 0x22, 0x22), 1.2};
        const double cxb = slot_rect.center().x(), cap = std::min(4.0, slot_rect.width() / 3);
        canvas.line({cxb, y_lo}, {cxb, y_hi}, whisker);
        canvas.line({cxb - cap, y_lo}, {cxb + cap, y_lo}, whisker);
        canvas.line({cxb - cap, y_hi}, {cxb + cap, y_hi}, whisker);
        label_y = std::min(label_y, y_hi);
      }
      // Large values need no decimals.
      const int decimals = std::abs(b.value) >= 100 ? 0 : std::abs(b.value) >= 10 ? std::min(chart.decimals, 1) : chart.decimals;
      const QString text = QString::number(b.value, 'f', decimals);
      const QSizeF size = Canvas::textSize(text, value_style);
      labels.push_back({QRectF(slot_rect.center().x() - size.width() / 2, label_y - 2 - size.height(), size.width(),
                               size.height()), text});
    }
    // A value is written above its bar unless it would touch another one: no label at all reads
    // better than two run together ("9595").
    for (size_t i = 0; i < labels.size(); ++i) {
      bool clear = labels[i].box.width() <= bar_w * 1.6;
      for (size_t k = 0; k < labels.size() && clear; ++k)
        if (k != i && labels[i].box.adjusted(-2, 0, 2, 0).intersects(labels[k].box)) clear = false;
      if (clear)
        canvas.text({labels[i].box.center().x(), labels[i].box.bottom()}, labels[i].text, value_style);
    }
  }
  canvas.line(box.bottomLeft(), box.bottomRight(), Stroke{kAxisColor, 1});
  canvas.line(box.bottomLeft(), box.topLeft(), Stroke{kAxisColor, 1});
}

}  // namespace demoplan::plot
