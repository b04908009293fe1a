#include "ui/widgets/calibration_error_plot.h"

#include <QHelpEvent>
#include <QPainter>
#include <QToolTip>
#include <algorithm>
#include <cmath>

namespace demoplan::ui {

CalibrationErrorPlot::CalibrationErrorPlot(QWidget* parent) : QWidget(parent) {
  setMinimumHeight(120);
  setAttribute(Qt::WA_OpaquePaintEvent);
}

void CalibrationErrorPlot::setCalibration(const std::vector<perception::CalibrationView>& views, double rms_px) {
  views_ = views;
  rms_px_ = rms_px;
  update();
}

void CalibrationErrorPlot::clear() {
  views_.clear();
  rms_px_ = 0.0;
  update();
}

QRectF CalibrationErrorPlot::plotArea() const { return QRectF(66, 22, width() - 76, height() - 46); }

double CalibrationErrorPlot::maxError() const {
  double m = rms_px_;
  for (const auto& v : views_)
    if (v.used) m = std::max(m, v.error_px);
  // A round top: 0.5, 1, 2, 5 ... pixels.
  for (double top : {0.25, 0.5, 1.0, 2.0, 5.0, 10.0, 20.0, 50.0})
    if (m <= top) return top;
  return std::ceil(m / 50.0) * 50.0;
}

int CalibrationErrorPlot::viewAt(double x) const {
  const QRectF a = plotArea();
  if (views_.empty() || x < a.left() || x >= a.right()) return -1;
  return std::min(static_cast<int>(views_.size()) - 1, static_cast<int>((x - a.left()) / a.width() * views_.size()));
}

void CalibrationErrorPlot::paintEvent(QPaintEvent*) {
  QPainter p(this);
  p.fillRect(rect(), palette().base());
  p.setRenderHint(QPainter::Antialiasing);
  const QRectF a = plotArea();
  p.setPen(palette().color(QPalette::Mid));
  p.drawRect(a);
  if (views_.empty()) {
    p.setPen(palette().color(QPalette::PlaceholderText));
    p.drawText(a, Qt::AlignCenter, tr("The error of each view shows here after calibrating"));
    return;
  }
  const double top = maxError();
  auto y_of = [&](double e) { return a.bottom() - std::min(e, top) / top * a.height(); };
  // Axis: 0, half and the top, in pixels.
  p.setPen(palette().color(QPalette::Text));
  for (double e : {0.0, top / 2, top}) {
    p.drawText(QRectF(0, y_of(e) - 8, a.left() - 6, 16), Qt::AlignRight | Qt::AlignVCenter,
               QString::number(e, 'g', 3) + QStringLiteral(" px"));
    p.setPen(QPen(palette().color(QPalette::Midlight), 1, Qt::DotLine));
    p.drawLine(QPointF(a.left(), y_of(e)), QPointF(a.right(), y_of(e)));
    p.setPen(palette().color(QPalette::Text));
  }
  const double w = a.width() / static_cast<double>(views_.size());
  for (size_t i = 0; i < views_.size(); ++i) {
    const auto& v = views_[i];
    const double x = a.left() + w * static_cast<double>(i);
    if (v.used) {
      const bool high = v.error_px > 2 * rms_px_;
      p.fillRect(QRectF(x + w * 0.15, y_of(v.error_px), w * 0.7, a.bottom() - y_of(v.error_px)),
                 high ? QColor(0xef, 0x6c, 0x00) : QColor(0x1e, 0x88, 0xe5));
    } else {
      p.fillRect(QRectF(x + w * 0.4, a.bottom() - 6, std::max(1.0, w * 0.2), 6), QColor(0x9e, 0x9e, 0x9e));
    }
  }
  p.setPen(QPen(QColor(0x2e, 0x7d, 0x32), 1.5, Qt::DashLine));
  p.drawLine(QPointF(a.left(), y_of(rms_px_)), QPointF(a.right(), y_of(rms_px_)));
  p.drawText(QRectF(a.left(), 2, a.width(), 18), Qt::AlignRight | Qt::AlignVCenter,
             tr("- - RMS %1 px over the views used").arg(rms_px_, 0, 'f', 3));
  p.setPen(palette().color(QPalette::Text));
  p.drawText(QRectF(a.left(), a.bottom() + 4, a.width(), 18), Qt::AlignCenter,
             tr("views in frame order (grey: left out; hover for why)"));
}

bool CalibrationErrorPlot::event(QEvent* e) {
  if (e->type() == QEvent::ToolTip) {
    const auto* h = static_cast<QHelpEvent*>(e);
    const int i = viewAt(h->pos().x());
    if (i < 0) {
      QToolTip::hideText();
      return true;
    }
    const auto& v = views_[static_cast<size_t>(i)];
    const QString where = v.image.empty() ? tr("frame %1").arg(v.frame) : QString::fromStdString(v.image);
    QToolTip::showText(h->globalPos(), v.used ? tr("%1: %2 px, %3 corners").arg(where).arg(v.error_px, 0, 'f', 3).arg(v.corners)
                                              : tr("%1: left out, %2").arg(where, QString::fromStdString(v.rejected)),
                       this);
    return true;
  }
  return QWidget::event(e);
}

}  // namespace demoplan::ui
