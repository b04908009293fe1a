#pragma once
// The export dialog's Joints view: for every exported joint, its position, velocity and
// acceleration against time, with the limits the export kept (dashed) and the rests shaded.
// Drawn with the plot library, so it looks like the figures the CLI writes.
#include <QString>
#include <QWidget>
#include <array>
#include <vector>

#include "core/export/export_job.h"
#include "plot/line_plot.h"

namespace demoplan::ui {

class JointPlotView : public QWidget {
  Q_OBJECT
public:
  explicit JointPlotView(QWidget* parent = nullptr);
  // `units` per configuration slot ("rad" or "m"); empty: rad.
  void setTrajectory(const ExportTrajectory& trajectory, const std::vector<QString>& units = {});
  // Shown instead of plots (e.g. why there is no trajectory).
  void setMessage(const QString& message);

  // One curve set (position, velocity, acceleration plots) per joint, in row order.
  int curveSets() const { return static_cast<int>(rows_.size()); }
  const std::vector<QString>& jointNames() const { return names_; }
  // Row r's plots: 0 position, 1 velocity, 2 acceleration.
  const plot::LinePlot& plotAt(int row, int quantity) const { return rows_.at(static_cast<size_t>(row))[static_cast<size_t>(quantity)]; }
  // The whole view as an image, at its current width (for tests and screenshots).
  QImage render(int width) const;

protected:
  void paintEvent(QPaintEvent*) override;

private:
  void draw(QPainter& painter, int width) const;
  int heightFor() const;
  std::vector<std::array<plot::LinePlot, 3>> rows_;
  std::vector<QString> names_;
  QString message_;
};

}  // namespace demoplan::ui
