#pragma once
// A Canvas on a QPainter: a QImage for PNG files, or a widget in its paintEvent.
#include <QPainter>

#include "plot/canvas.h"

namespace demoplan::plot {

class PainterCanvas : public Canvas {
public:
  explicit PainterCanvas(QPainter& painter) : p_(painter) {}
  void fillRect(const QRectF& r, const QColor& c) override;
  void strokeRect(const QRectF& r, const Stroke& s) override;
  void line(QPointF a, QPointF b, const Stroke& s) override;
  void polyline(const std::vector<QPointF>& points, const Stroke& s) override;
  void text(QPointF anchor, const QString& text, const TextStyle& style) override;
  void beginClip(const QRectF& r) override;
  void endClip() override;

private:
  void setPen(const Stroke& s);
  QPainter& p_;
};

}  // namespace demoplan::plot
