#pragma once
// Saves a drawing as SVG or PNG, chosen by the file's extension.
#include <QSizeF>
#include <QString>
#include <functional>

#include "plot/canvas.h"

namespace demoplan::plot {

// PNG pixels are `png_scale` times the drawing's units (crisp text); SVG keeps the units.
// Returns an empty string on success, else why not (unknown extension, cannot write).
QString save_figure(const QString& file, QSizeF size, const QString& title,
                    const std::function<void(Canvas&)>& draw, double png_scale = 2.0);
// True for the extensions save_figure knows (.svg, .png).
bool is_figure_file(const QString& file);

}  // namespace demoplan::plot
