#pragma once
// One part's pose track under the timeline, on the timeline's frame axis (FrameAxis), so the
// operator sees why the detector put an event where it is: the position (x, y, z in mm from
// the part's first rest) and the rotation (degrees from the first rest's orientation) against
// the frame, the segmentation behind them (rests, carries, rides, other motions; a band on top
// names each), under that band how sure the tracker was of each frame (green, amber below 0.8,
// red below kLowConfidence, grey where it did not see the part), the doubts hatched, the
// demonstration's grasps and releases of the part as vertical lines and the playhead. Click or
// drag moves the playhead; the tooltip reads the values, the confidence and the segment at the
// cursor.
#include <QWidget>
#include <array>
#include <memory>
#include <vector>

#include "ui/document/document.h"
#include "ui/widgets/frame_axis.h"

namespace demoplan::ui {

class PartTracksView : public QWidget {
  Q_OBJECT
public:
  explicit PartTracksView(Document* doc, QWidget* parent = nullptr);

  // The track row shown (perception::PoseTracks order); -1: none.
  void setRow(int row);
  int row() const { return row_; }
  const perception::TracksDemonstration* tracks() const { return tracks_.get(); }

  // Geometry, public for tests.
  FrameAxis axis() const { return {double(width()), doc_->frameCount()}; }
  QRectF segmentBand() const;
  QRectF confidenceStrip() const;
  QRectF positionPlot() const;
  QRectF anglePlot() const;  // empty when the view is too short for it
  bool showsAngle() const;
  static constexpr int kMinHeightWithAngle = 120;
  // The colour of `frame` in the confidence strip (invalid past the track's end).
  QColor confidenceColor(int frame) const;
  // The segment of the shown row covering `frame`; -1 when none.
  int segmentAt(int frame) const;
  // What the tooltip says at `x`: the frame, the values, the segment and any doubt there.
  QString toolTipAt(double x) const;
  QSize sizeHint() const override;
  QSize minimumSizeHint() const override;

signals:
  // The tracks were fetched again (a detection, another project, first shown).
  void tracksReloaded();

protected:
  void paintEvent(QPaintEvent*) override;
  void mousePressEvent(QMouseEvent*) override;
  void mouseMoveEvent(QMouseEvent*) override;
  void mouseReleaseEvent(QMouseEvent*) override;
  bool event(QEvent*) override;
  void showEvent(QShowEvent*) override;

private:
  // A frame range of the shown part the detector could not decide.
  struct Doubt {
    int first = 0, last = 0;
    QString message;
  };
  void reload();  // the document's tracks, then the row's series
  void computeSeries();
  std::vector<Doubt> doubts() const;
  int demonstrationObject() const;  // the row's index in the demonstration; -1: not planned
  void paintSegments(QPainter& p) const;
  void paintConfidence(QPainter& p) const;
  void paintStrip(QPainter& p, const QRectF& box, int first_series, int series, double lo, double hi,
                  const QString& title) const;
  void paintMarks(QPainter& p) const;

  Document* doc_;
  std::shared_ptr<const perception::TracksDemonstration> tracks_;
  int row_ = -1;
  // Per frame: x, y, z (mm) and the angle (deg) from the first rest; NaN where not seen.
  std::vector<std::array<double, 4>> series_;
  std::vector<double> confidence_;  // per frame, the tracker's; NaN where not seen
  double pos_lo_ = -1, pos_hi_ = 1, ang_lo_ = 0, ang_hi_ = 1;
  bool scrubbing_ = false;
};

}  // namespace demoplan::ui
