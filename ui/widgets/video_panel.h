#pragma once
// The video panel: the current frame of the recording with the parts' outlines at their
// demonstrated poses (their meshes projected through the calibrated camera, so a wrong pose is
// visible at a glance; on the start frame of the part-model tracker, their silhouette edges at
// the poses it starts from: start_pose_outlines.h) and, on request, the ArUco markers found in
// the frame; a transport bar
// (play/pause, step, slider, frame and time). Drop a video file on it to open it.
#include <QImage>
#include <QWidget>
#include <memory>
#include <vector>

#include "ui/document/document.h"
#include "ui/widgets/start_pose_outlines.h"
#include "ui/widgets/transport.h"

class QCheckBox;
class QLabel;
class QSlider;
class QToolButton;

namespace demoplan::perception {
class MarkerDetector;
}

class QDragEnterEvent;
class QDropEvent;

namespace demoplan::ui {

class FrameView : public QWidget {
  Q_OBJECT
public:
  explicit FrameView(Document* doc, QWidget* parent = nullptr);
  ~FrameView() override;
  void setShowOutlines(bool on);
  void setShowMarkers(bool on);
  const QImage& image() const { return image_; }
  // The outline of each part in image pixels (empty when it cannot be drawn).
  const std::vector<QPolygonF>& outlines() const { return outlines_; }
  // The outlines at the part-model tracker's start poses (drawn in place of those above).
  const StartPoseOutlines& startPoses() const { return start_poses_; }
  QSize sizeHint() const override { return {480, 270}; }

protected:
  void paintEvent(QPaintEvent*) override;

private:
  void reloadFrame();
  void rebuildModels();
  void computeOverlay();

  Document* doc_;
  QImage image_;
  int image_frame_ = -1;
  QString error_;
  bool show_outlines_ = true, show_markers_ = false;
  std::vector<std::vector<Eigen::Vector3d>> model_points_;  // per object, object frame
  std::vector<QPolygonF> outlines_;
  StartPoseOutlines start_poses_;
  struct Marker {
    int id;
    QPolygonF corners;
  };
  std::vector<Marker> markers_;
  std::unique_ptr<perception::MarkerDetector> detector_;
};

class VideoPanel : public QWidget {
  Q_OBJECT
public:
  VideoPanel(Document* doc, Transport* transport, QWidget* parent = nullptr);
  FrameView* frameView() const { return view_; }
  QSlider* slider() const { return slider_; }

signals:
  void openVideoRequested();

protected:
  void dragEnterEvent(QDragEnterEvent*) override;
  void dropEvent(QDropEvent*) override;

private:
  void refresh();
  Document* doc_;
  Transport* transport_;
  FrameView* view_;
  QSlider* slider_;
  QLabel* position_;
  QToolButton* play_;
};

bool isVideoFile(const QString& path);

}  // namespace demoplan::ui
