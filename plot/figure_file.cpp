#include "plot/figure_file.h"

#include <QFile>
#include <QImage>
#include <QPainter>
#include <QSaveFile>

#include "plot/painter_canvas.h"
#include "plot/svg_canvas.h"

namespace demoplan::plot {

bool is_figure_file(const QString& file) {
  return file.endsWith(QLatin1String(".svg"), Qt::CaseInsensitive) ||
         file.endsWith(QLatin1String(".png"), Qt::CaseInsensitive);
}

QString save_figure(const QString& file, QSizeF size, const QString& title,
                    const std::function<void(Canvas&)>& draw, double png_scale) {
  if (file.endsWith(QLatin1String(".svg"), Qt::CaseInsensitive)) {
    SvgCanvas svg(size, title);
    svg.fillRect(QRectF(QPointF(0, 0), size), Qt::white);
    draw(svg);
    QSaveFile out(file);
    if (!out.open(QIODevice::WriteOnly) || out.write(svg.document().toUtf8()) < 0 || !out.commit())
      return QStringLiteral("cannot write it: ") + out.errorString();
    return {};
  }
  if (file.endsWith(QLatin1String(".png"), Qt::CaseInsensitive)) {
    QImage image((size * png_scale).toSize(), QImage::Format_ARGB32_Premultiplied);
    image.fill(Qt::white);
    {
      QPainter p(&image);
      p.setRenderHint(QPainter::Antialiasing);
      p.setRenderHint(QPainter::TextAntialiasing);
      p.scale(png_scale, png_scale);
      PainterCanvas canvas(p);
      draw(canvas);
    }
    image.setText(QStringLiteral("Title"), title);
    if (!image.save(file, "PNG")) return QStringLiteral("cannot write it");
    return {};
  }
  return QStringLiteral("the figure's file must end in .svg or .png");
}

}  // namespace demoplan::plot
