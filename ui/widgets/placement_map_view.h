#pragma once
// The placement search's heat map in the Placement panel (plot/heat_map.h, as the CLI draws it):
// each candidate base pose a square at its place, coloured by its cycle time, grey without a
// valid plan, a tick along its yaw; the robot's base crossed, the best ringed. Hovering tells a
// candidate's numbers or why it cannot be used; a click chooses it, a double click stands the
// robot there.
#include <QWidget>

#include "plot/heat_map.h"
#include "ui/document/document.h"

namespace demoplan::ui {

class PlacementMapView : public QWidget {
  Q_OBJECT
public:
  explicit PlacementMapView(Document* doc, QWidget* parent = nullptr);
  QSize sizeHint() const override { return {460, 340}; }
  // The candidate (an index into the search's candidates) under a pixel, -1 for none.
  int candidateAt(QPointF pixel) const;
  int chosen() const { return chosen_; }
  void choose(int candidate);
  // What the tooltip says of a candidate.
  QString describe(int candidate) const;

signals:
  void chosenChanged(int candidate);
  // A double click: stand the robot on this candidate.
  void standRequested(int candidate);

protected:
  void paintEvent(QPaintEvent*) override;
  void mousePressEvent(QMouseEvent*) override;
  void mouseDoubleClickEvent(QMouseEvent*) override;
  bool event(QEvent*) override;

private:
  plot::HeatMap map() const;
  QRectF area() const { return QRectF(rect()).adjusted(6, 6, -6, -6); }

  void refreshOutlines();

  Document* doc_;
  int chosen_ = -1;
  std::vector<std::vector<QPointF>> outlines_;  // the furniture from above, for the map
};

}  // namespace demoplan::ui
