#include "plot/canvas.h"

#include <QFontMetricsF>

namespace demoplan::plot {

QFont Canvas::font(const TextStyle& style) {
  // DejaVu Sans is on every Debian desktop; the SVG names the same family first.
  QFont f(QStringLiteral("DejaVu Sans"));
  f.setPixelSize(std::max(1, static_cast<int>(std::lround(style.size))));
  f.setBold(style.bold);
  return f;
}

QSizeF Canvas::textSize(const QString& text, const TextStyle& style) {
  const QFontMetricsF m(font(style));
  return {m.horizontalAdvance(text), m.ascent() + m.descent()};
}

QPointF Canvas::baselineOrigin(QPointF anchor, const QString& text, const TextStyle& style) {
  const QFontMetricsF m(font(style));
  const double w = m.horizontalAdvance(text);
  double x = anchor.x(), y = anchor.y();
  if (style.align & Qt::AlignHCenter) x -= w / 2;
  else if (style.align & Qt::AlignRight) x -= w;
  if (style.align & Qt::AlignVCenter) y += (m.ascent() - m.descent()) / 2;
  else if (style.align & Qt::AlignBottom) y -= m.descent();
  else y += m.ascent();
  return {x, y};
}

}  // namespace demoplan::plot
