#include "ui/widgets/joint_plot_view.h"

#include <QImage>
#include <QPainter>
#include <cmath>

#include "plot/legend.h"
#include "plot/painter_canvas.h"
#include "plot/palette.h"

namespace demoplan::ui {

namespace {

constexpr int kLegendH = 34, kRowH = 140, kNameW = 26;

}  // namespace

JointPlotView::JointPlotView(QWidget* parent) : QWidget(parent) {
  setAutoFillBackground(true);
  QPalette p = palette();
  p.setColor(QPalette::Window, Qt::white);
  setPalette(p);
  setMinimumHeight(heightFor());
}

void JointPlotView::setMessage(const QString& message) {
  rows_.clear();
  names_.clear();
  message_ = message;
  setMinimumHeight(heightFor());
  update();
}

void JointPlotView::setTrajectory(const ExportTrajectory& t, const std::vector<QString>& units) {
  rows_.clear();
  names_.clear();
  message_.clear();
  static const char* kQuantity[3] = {"position", "velocity", "acceleration"};
  static const char* kSuffix[3] = {"", "/s", "/s²"};  // UTF-8
  for (int j : t.joints) {
    const auto slot = static_cast<size_t>(j);
    const QString name = slot < t.limits.names.size() ? QString::fromStdString(t.limits.names[slot])
                                                      : QStringLiteral("joint %1").arg(j);
    const QString unit = slot < units.size() && !units[slot].isEmpty() ? units[slot] : QStringLiteral("rad");
    std::array<plot::LinePlot, 3> row;
    for (int k = 0; k < 3; ++k) {
      plot::LinePlot& p = row[static_cast<size_t>(k)];
      p.min_tick_width = 26;
      // The joint's name is the row's label; the time axis is named under the last row only.
      p.title = QStringLiteral("%1 (%2%3)").arg(QLatin1String(kQuantity[k]), unit, QString::fromUtf8(kSuffix[k]));
      plot::Curve c{QLatin1String(kQuantity[k]), plot::quantity_color(k), {}};
      c.points.reserve(t.samples.size());
      for (const TrajectorySample& s : t.samples) {
        const Eigen::VectorXd& x = k == 0 ? s.q : k == 1 ? s.v : s.a;
        if (j < x.size()) c.points.emplace_back(s.t, x[j]);
      }
      p.curves.push_back(std::move(c));
      // The limits the export kept (scaled by the dialog's percentages): dashed.
      const auto& L = t.limits;
      if (k == 0 && j < L.lower.size()) {
        if (std::isfinite(L.lower[j])) p.limits.push_back({L.lower[j], plot::kLimitColor});
        if (std::isfinite(L.upper[j])) p.limits.push_back({L.upper[j], plot::kLimitColor});
      }
      const Eigen::VectorXd* bound = k == 1 ? &L.velocity : k == 2 ? &L.acceleration : nullptr;
      if (bound && j < bound->size()) {
        p.limits.push_back({(*bound)[j], plot::kLimitColor});
        p.limits.push_back({-(*bound)[j], plot::kLimitColor});
      }
      for (double r : t.rest_times) p.intervals.push_back({r, r, plot::kRestColor});
    }
    rows_.push_back(std::move(row));
    names_.push_back(name);
  }
  if (rows_.empty()) message_ = tr("No joints to plot.");
  else
    for (plot::LinePlot& p : rows_.back()) p.x_label = tr("time (s)");
  setMinimumHeight(heightFor());
  update();
}

int JointPlotView::heightFor() const {
  return rows_.empty() ? 120 : kLegendH + kRowH * static_cast<int>(rows_.size()) + 24;  // + the time axis' name
}

void JointPlotView::draw(QPainter& painter, int width) const {
  painter.setRenderHint(QPainter::Antialiasing);
  plot::PainterCanvas canvas(painter);
  if (rows_.empty()) {
    canvas.text({width / 2.0, 50}, message_.isEmpty() ? tr("No trajectory") : message_,
                plot::TextStyle{.size = 13, .color = QColor(0x77, 0x77, 0x77), .align = Qt::AlignHCenter | Qt::AlignTop});
    return;
  }
  const std::vector<plot::LegendEntry> legend{
      {tr("position"), plot::quantity_color(0), true},
      {tr("velocity"), plot::quantity_color(1), true},
      {tr("acceleration"), plot::quantity_color(2), true},
      {tr("limit (as exported)"), plot::kLimitColor, true, true},
      {tr("robot at rest (ends, grasps, releases)"), plot::kRestColor.darker(110)}};
  plot::draw_legend(canvas, QRectF(0, 6, width, kLegendH - 6), legend, 11.5);
  const double col_w = (width - kNameW) / 3.0;
  for (size_t r = 0; r < rows_.size(); ++r) {
    const double top = kLegendH + kRowH * static_cast<double>(r);
    canvas.text({4, top + kRowH / 2.0}, names_[r],
                plot::TextStyle{.size = 12, .bold = true, .align = Qt::AlignHCenter | Qt::AlignTop, .vertical = true});
    if (r > 0) canvas.line({4, top - 4}, {width - 4.0, top - 4}, plot::Stroke{plot::kGridColor, 1});
    for (int k = 0; k < 3; ++k)
      plot::draw_line_plot(canvas, QRectF(kNameW + col_w * k, top, col_w - 6, kRowH - 10 + (r + 1 == rows_.size() ? 16 : 0)),
                           rows_[r][static_cast<size_t>(k)]);
  }
}

void JointPlotView::paintEvent(QPaintEvent*) {
  QPainter p(this);
  draw(p, width());
}

QImage JointPlotView::render(int width) const {
  QImage image(width, heightFor(), QImage::Format_ARGB32_Premultiplied);
  image.fill(Qt::white);
  QPainter p(&image);
  draw(p, width);
  return image;
}

}  // namespace demoplan::ui
