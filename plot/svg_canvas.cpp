#include "plot/svg_canvas.h"

#include <QRegularExpression>

namespace demoplan::plot {

namespace {

QString num(double v) { return QString::number(v, 'f', 2).remove(QRegularExpression(QStringLiteral("\\.?0+$"))); }

// fill="#rrggbb" (with fill-opacity when translucent); `what` is fill or stroke.
QString paint(const char* what, const QColor& c) {
  QString s = QStringLiteral("%1=\"%2\"").arg(QLatin1String(what), c.name(QColor::HexRgb));
  if (c.alpha() < 255) s += QStringLiteral(" %1-opacity=\"%2\"").arg(QLatin1String(what), num(c.alphaF()));
  return s;
}

QString fill(const QColor& c) { return paint("fill", c); }

QString stroke(const Stroke& st) {
  QString s = QStringLiteral("fill=\"none\" ") + paint("stroke", st.color);
  s += QStringLiteral(" stroke-width=\"%1\"").arg(num(st.width));
  if (st.dashed) s += QStringLiteral(" stroke-dasharray=\"5 3\"");
  return s;
}

}  // namespace

SvgCanvas::SvgCanvas(QSizeF size, const QString& title) : size_(size), title_(title) {}

void SvgCanvas::fillRect(const QRectF& r, const QColor& c) {
  body_ += QStringLiteral("<rect x=\"%1\" y=\"%2\" width=\"%3\" height=\"%4\" %5/>\n")
               .arg(num(r.x()), num(r.y()), num(r.width()), num(r.height()), fill(c));
}

void SvgCanvas::strokeRect(const QRectF& r, const Stroke& s) {
  body_ += QStringLiteral("<rect x=\"%1\" y=\"%2\" width=\"%3\" height=\"%4\" %5/>\n")
               .arg(num(r.x()), num(r.y()), num(r.width()), num(r.height()), stroke(s));
}

void SvgCanvas::line(QPointF a, QPointF b, const Stroke& s) {
  body_ += QStringLiteral("<line x1=\"%1\" y1=\"%2\" x2=\"%3\" y2=\"%4\" %5/>\n")
               .arg(num(a.x()), num(a.y()), num(b.x()), num(b.y()), stroke(s));
}

void SvgCanvas::polyline(const std::vector<QPointF>& points, const Stroke& s) {
  if (points.size() < 2) return;
  QString pts;
  for (const QPointF& p : points) pts += num(p.x()) + QLatin1Char(',') + num(p.y()) + QLatin1Char(' ');
  body_ += QStringLiteral("<polyline points=\"%1\" %2 stroke-linejoin=\"round\"/>\n").arg(pts.trimmed(), stroke(s));
}

void SvgCanvas::text(QPointF anchor, const QString& text, const TextStyle& style) {
  // The baseline is placed as the PNG places it, from the same font metrics.
  QString transform;
  QPointF a = anchor;
  if (style.vertical) {
    transform = QStringLiteral(" transform=\"translate(%1 %2) rotate(-90)\"").arg(num(anchor.x()), num(anchor.y()));
    a = {0, 0};
  }
  QPointF o = Canvas::baselineOrigin(a, text, style);
  QString anchorAttr = QStringLiteral("start");
  if (style.align & Qt::AlignHCenter) {
    anchorAttr = QStringLiteral("middle");
    o.setX(a.x());
  } else if (style.align & Qt::AlignRight) {
    anchorAttr = QStringLiteral("end");
    o.setX(a.x());
  }
  body_ += QStringLiteral("<text x=\"%1\" y=\"%2\" font-family=\"DejaVu Sans, Verdana, sans-serif\" "
                          "font-size=\"%3\"%4 text-anchor=\"%5\" fill=\"%6\"%7>%8</text>\n")
               .arg(num(o.x()), num(o.y()), num(style.size),
                    style.bold ? QStringLiteral(" font-weight=\"bold\"") : QString(), anchorAttr,
                    style.color.name(), transform, text.toHtmlEscaped());
}

void SvgCanvas::beginClip(const QRectF& r) {
  const int id = ++clips_;
  body_ += QStringLiteral("<clipPath id=\"clip%1\"><rect x=\"%2\" y=\"%3\" width=\"%4\" height=\"%5\"/></clipPath>\n"
                          "<g clip-path=\"url(#clip%1)\">\n")
               .arg(id)
               .arg(num(r.x()), num(r.y()), num(r.width()), num(r.height()));
}

void SvgCanvas::endClip() { body_ += QStringLiteral("</g>\n"); }

void SvgCanvas::beginGroup(const QString& id) {
  body_ += QStringLiteral("<g id=\"%1\">\n").arg(id.toHtmlEscaped());
}

void SvgCanvas::endGroup() { body_ += QStringLiteral("</g>\n"); }

QString SvgCanvas::document() const {
  return QStringLiteral("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
                        "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%1\" height=\"%2\" viewBox=\"0 0 %1 %2\">\n"
                        "<title>%3</title>\n")
             .arg(num(size_.width()), num(size_.height()), title_.toHtmlEscaped()) +
         body_ + QStringLiteral("</svg>\n");
}

}  // namespace demoplan::plot
