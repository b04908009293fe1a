#include "plot/painter_canvas.h"

namespace demoplan::plot {

void PainterCanvas::setPen(const Stroke& s) {
  QPen pen(s.color, s.width);
  if (s.dashed) pen.setDashPattern({5.0 / std::max(s.width, 0.5), 3.0 / std::max(s.width, 0.5)});
  pen.setCapStyle(Qt::FlatCap);
  pen.setJoinStyle(Qt::RoundJoin);
  p_.setPen(pen);
  p_.setBrush(Qt::NoBrush);
}

void PainterCanvas::fillRect(const QRectF& r, const QColor& c) { p_.fillRect(r, c); }

void PainterCanvas::strokeRect(const QRectF& r, const Stroke& s) {
  setPen(s);
  p_.drawRect(r);
}

void PainterCanvas::line(QPointF a, QPointF b, const Stroke& s) {
  setPen(s);
  p_.drawLine(a, b);
}

void PainterCanvas::polyline(const std::vector<QPointF>& points, const Stroke& s) {
  if (points.size() < 2) return;
  setPen(s);
  p_.drawPolyline(points.data(), static_cast<int>(points.size()));
}

void PainterCanvas::text(QPointF anchor, const QString& text, const TextStyle& style) {
  p_.save();
  p_.setFont(font(style));
  p_.setPen(style.color);
  if (style.vertical) {
    p_.translate(anchor);
    p_.rotate(-90);
    anchor = {0, 0};
  }
  p_.drawText(baselineOrigin(anchor, text, style), text);
  p_.restore();
}

void PainterCanvas::beginClip(const QRectF& r) {
  p_.save();
  p_.setClipRect(r);
}

void PainterCanvas::endClip() { p_.restore(); }

}  // namespace demoplan::plot
