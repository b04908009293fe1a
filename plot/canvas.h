#pragma once
// What a plot draws on. The plots only use these few primitives, so one drawing serves a PNG or
// a widget (PainterCanvas) and an SVG file (SvgCanvas). Text is measured with the same font on
// both, so the layout is the same.
#include <QColor>
#include <QFont>
#include <QPointF>
#include <QRectF>
#include <QSizeF>
#include <QString>
#include <vector>

namespace demoplan::plot {

struct Stroke {
  QColor color = Qt::black;
  double width = 1.0;
  bool dashed = false;
};

struct TextStyle {
  double size = 11.0;  // px
  bool bold = false;
  QColor color = QColor(0x22, 0x22, 0x22);
  // Where the anchor point is on the text's box: left/center/right, top/center/bottom.
  Qt::Alignment align = Qt::AlignLeft | Qt::AlignTop;
  bool vertical = false;  // rotated 90° counter-clockwise about the anchor (y-axis titles)
};

class Canvas {
public:
  virtual ~Canvas() = default;
  virtual void fillRect(const QRectF& r, const QColor& c) = 0;
  virtual void strokeRect(const QRectF& r, const Stroke& s) = 0;
  virtual void line(QPointF a, QPointF b, const Stroke& s) = 0;
  virtual void polyline(const std::vector<QPointF>& points, const Stroke& s) = 0;
  // `anchor` is the point of the text's box named by style.align.
  virtual void text(QPointF anchor, const QString& text, const TextStyle& style) = 0;
  // Everything drawn until the matching end is clipped to `r` (not nested).
  virtual void beginClip(const QRectF& r) = 0;
  virtual void endClip() = 0;
  // A named group (an SVG <g id=...>): lets tools and tests find a figure's panels.
  virtual void beginGroup(const QString& id) {}
  virtual void endGroup() {}

  static QFont font(const TextStyle& style);
  static QSizeF textSize(const QString& text, const TextStyle& style);
  // The baseline's left end of a horizontal text whose box has style.align at `anchor`.
  static QPointF baselineOrigin(QPointF anchor, const QString& text, const TextStyle& style);
};

}  // namespace demoplan::plot
