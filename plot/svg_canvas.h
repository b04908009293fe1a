#pragma once
// A Canvas that writes SVG text: real <text> elements (selectable, scalable) and one <g id=...>
// per group, which QSvgGenerator cannot give.
#include <QString>

#include "plot/canvas.h"

namespace demoplan::plot {

class SvgCanvas : public Canvas {
public:
  SvgCanvas(QSizeF size, const QString& title);
  void fillRect(const QRectF& r, const QColor& c) override;
  void strokeRect(const QRectF& r, const Stroke& s) override;
  void line(QPointF a, QPointF b, const Stroke& s) override;
  void polyline(const std::vector<QPointF>& points, const Stroke& s) override;
  void text(QPointF anchor, const QString& text, const TextStyle& style) override;
  void beginClip(const QRectF& r) override;
  void endClip() override;
  void beginGroup(const QString& id) override;
  void endGroup() override;
  // The whole document, closed.
  QString document() const;

private:
  QString body_;
  QSizeF size_;
  QString title_;
  int clips_ = 0;
};

}  // namespace demoplan::plot
