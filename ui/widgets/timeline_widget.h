#pragma once
// The event timeline: one lane per part with its grasp (green, pointing up) and release (orange,
// pointing down) markers, the carrying interval between them, each event's confidence, the
// playhead, the rule each broken event violates, and the detection's doubts (frame ranges it
// could not decide, hatched amber, the reason as tooltip). Click selects, drag moves an event to
// another frame, double-click adds one, the context menu adds or deletes; every edit goes
// through the document's undo stack.
#include <QWidget>

#include "ui/document/document.h"
#include "ui/widgets/frame_axis.h"

class QComboBox;
class QLabel;
class QPainter;
class QProgressBar;
class QPushButton;

namespace demoplan::ui {

class TimelineWidget : public QWidget {
  Q_OBJECT
public:
  explicit TimelineWidget(Document* doc, QWidget* parent = nullptr);

  // Geometry, public for tests and for the panel around it.
  double frameToX(double frame) const;
  int xToFrame(double x) const;
  int laneTop(int object) const;
  QRectF markerRect(int event) const;
  int eventAt(const QPointF& p) const;  // -1 when none
  QRectF doubtRect(int doubt) const;    // of Demonstration::doubts[doubt], in its part's lane
  int doubtAt(const QPointF& p) const;  // -1 when none
  QRectF correctionRect(int index) const;  // of Document::corrections()[index], in its part's lane
  int correctionAt(const QPointF& p) const;  // -1 when none
  int laneAt(double y) const;           // -1 when none
  QSize sizeHint() const override;
  QSize minimumSizeHint() const override;

  static constexpr int kGutter = FrameAxis::kGutter;
  static constexpr int kRuler = 22;
  static constexpr int kLane = 30;

protected:
  void paintEvent(QPaintEvent*) override;
  void mousePressEvent(QMouseEvent*) override;
  void mouseMoveEvent(QMouseEvent*) override;
  void mouseReleaseEvent(QMouseEvent*) override;
  void mouseDoubleClickEvent(QMouseEvent*) override;
  void contextMenuEvent(QContextMenuEvent*) override;
  bool event(QEvent*) override;

private:
  void paintMarker(QPainter& p, int event, double x, bool ghost) const;
  double right() const;
  FrameAxis axis() const;

  Document* doc_;
  enum class Drag { None, Playhead, Event } drag_ = Drag::None;
  int drag_event_ = -1;
  int drag_frame_ = 0;
  QPointF press_pos_;
  bool drag_moved_ = false;
};

// The timeline with the demonstration's validity under it: the rule that breaks and where,
// as links that jump to the offending event.
class TimelinePanel : public QWidget {
  Q_OBJECT
public:
  explicit TimelinePanel(Document* doc, QWidget* parent = nullptr);
  TimelineWidget* timeline() const { return timeline_; }
  QLabel* validityLabel() const { return validity_; }
  QPushButton* detectButton() const { return detect_; }
  QComboBox* trackerChoice() const { return tracker_; }
  QLabel* detectionLabel() const { return detection_; }
  QLabel* detectionWarningsLabel() const { return warnings_; }
  // Jumps to the issue at `index` of Document::issues() (what clicking its link does).
  void jumpToIssue(int index);
  // Selects the part of Demonstration::doubts[index] and moves the playhead to its first frame.
  void jumpToDoubt(int index);
  // The next doubt after the playhead (else the first); returns its index, -1 when none.
  int jumpToNextDoubt();

private:
  void refresh();
  void refreshDetection();
  // The extraction's warnings, on their own line (hidden when there are none).
  void showDetectionWarnings(const std::vector<std::string>& warnings);
  Document* doc_;
  TimelineWidget* timeline_;
  QLabel* validity_;
  QPushButton* detect_;
  QComboBox* tracker_;
  QPushButton* cancel_;
  QProgressBar* progress_;
  QLabel* detection_;
  QLabel* warnings_;
};

}  // namespace demoplan::ui
