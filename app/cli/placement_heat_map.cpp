// The placement search's heat map (needs the build with Qt 6): each candidate base pose a square
// at its (x, y), coloured by the cycle time of its best valid plan, grey where it has none, a
// tick pointing along its yaw, the best ringed.
#include <cmath>

#include "app/cli/offscreen_gui.h"
#include "app/cli/placement_summary.h"
#include "core/error.h"
#include "plot/figure_file.h"
#include "plot/heat_map.h"

namespace demoplan::cli {

void write_placement_heat_map(const std::string& file, const PlacementResult& r) {
  const QString out = QString::fromStdString(file);
  if (!plot::is_figure_file(out)) throw InputError("command line", "--heat-map", "the file must end in .svg or .png");
  const PlacementRegion region = parse_placement_region(r.arguments.at("region").get<std::string>(), "region");
  const OffscreenGui gui;  // fonts
  plot::HeatMap map;
  const nlohmann::json& a = r.arguments;
  const std::string what = a.contains("cell") ? a["cell"].get<std::string>()
                                              : a.value("task", std::string()) + ", " + a.value("robot", std::string());
  map.title = QString::fromStdString("Where to put the robot: " + what);
  map.x_label = QStringLiteral("x (m)");
  map.y_label = QStringLiteral("y (m)");
  map.value_label = QStringLiteral("cycle time (s)");
  map.grey_label = QStringLiteral("no valid plan");
  map.marked_label = QStringLiteral("best");
  map.x0 = region.x.low, map.x1 = region.x.high, map.y0 = region.y.low, map.y1 = region.y.high;
  map.cell = 0.9 * std::sqrt((map.x1 - map.x0) * (map.y1 - map.y0) / std::max<size_t>(r.candidates.size(), 1));
  for (const PlacementCandidate& c : r.candidates)
    map.samples.push_back({c.base.x, c.base.y, c.usable() ? *c.cycle_time_s() : std::nan(""), c.base.yaw});
  for (const PlacementCandidate& c : r.published) map.references.push_back({c.base.x, c.base.y});
  map.references_label = QStringLiteral("published poses");
  for (const Footprint& f : r.furniture) {
    auto& polygon = map.outlines.emplace_back();
    for (const Eigen::Vector2d& p : f.outline) polygon.emplace_back(p.x(), p.y());
  }
  map.outlines_label = QStringLiteral("furniture");
  if (!r.candidates.empty() && r.candidates.front().usable())
    map.marked.push_back({r.candidates.front().base.x, r.candidates.front().base.y});
  const QString error = plot::save_figure(out, QSizeF(720, 560), map.title,
                                          [&](plot::Canvas& canvas) { draw_heat_map(canvas, QRectF(16, 16, 688, 528), map); });
  if (!error.isEmpty()) throw InputError(file, "", error.toStdString());
}

}  // namespace demoplan::cli
