#include "ui/widgets/video_panel.h"

#include <QCheckBox>
#include <QDragEnterEvent>
#include <QDropEvent>
#include <QFileInfo>
#include <QHBoxLayout>
#include <QLabel>
#include <QMimeData>
#include <QPainter>
#include <QSignalBlocker>
#include <QSlider>
#include <QStyle>
#include <QToolButton>
#include <QVBoxLayout>
#include <opencv2/imgproc.hpp>

#include "perception/camera/camera_model.h"
#include "perception/markers/marker_detector.h"
#include "perception/video/video_reader.h"
#include "ui/document/demo_poses.h"
#include "ui/widgets/style.h"

namespace demoplan::ui {

bool isVideoFile(const QString& path) {
  static const QStringList ext = {"mp4", "avi", "mkv", "mov", "m4v", "webm", "mpg", "mpeg"};
  return ext.contains(QFileInfo(path).suffix().toLower());
}

FrameView::FrameView(Document* doc, QWidget* parent) : QWidget(parent), doc_(doc) {
  setMinimumSize(240, 135);
  setAttribute(Qt::WA_OpaquePaintEvent);
  connect(doc_, &Document::currentFrameChanged, this, &FrameView::reloadFrame);
  connect(doc_->media(), &Media::videoChanged, this, [this] {
    image_frame_ = -1;
    reloadFrame();
  });
  connect(doc_, &Document::projectLoaded, this, [this] {
    rebuildModels();
    image_frame_ = -1;
    reloadFrame();
  });
  auto overlay = [this] {
    computeOverlay();
    update();
  };
  connect(doc_, &Document::sceneChanged, this, [this, overlay] {
    rebuildModels();
    overlay();
  });
  connect(doc_->media(), &Media::cameraChanged, this, [this, overlay] {
    detector_.reset();
    start_poses_.forgetOutlines();
    overlay();
  });
  connect(doc_, &Document::demonstrationChanged, this, overlay);
  connect(doc_, &Document::selectionChanged, this, overlay);
  connect(doc_, &Document::displayChanged, this, overlay);
  // Which tracker, and with the marker scene where init.json may lie, where the parts start.
  connect(doc_->detection(), &EventDetection::trackerChanged, this, overlay);
  connect(doc_->media(), &Media::markersChanged, this, overlay);
  rebuildModels();
  reloadFrame();
}

FrameView::~FrameView() = default;

void FrameView::setShowOutlines(bool on) {
  show_outlines_ = on;
  computeOverlay();
  update();
}

void FrameView::setShowMarkers(bool on) {
  show_markers_ = on;
  image_frame_ = -1;
  reloadFrame();
}

void FrameView::rebuildModels() {
  model_points_.clear();
  start_poses_.forgetMeshes();
  if (!doc_->hasProject()) return;
  for (const SceneObject& o : doc_->scene().objects) {
    std::vector<Eigen::Vector3d> pts;
    for (const Link& link : o.model.links) {
      if (link.parent_joint >= 0) continue;  // the root link carries the object's pose
      for (const Geometry& g : link.visuals.empty() ? link.collisions : link.visuals) {
        if (const auto* m = std::get_if<MeshShape>(&g.shape); m && m->mesh) {
          const auto& v = m->mesh->vertices;
          const size_t stride = std::max<size_t>(1, v.size() / 1500);
          for (size_t i = 0; i < v.size(); i += stride)
            pts.push_back(g.origin * (v[i].cast<double>().cwiseProduct(m->scale)));
        } else if (const auto* b = std::get_if<BoxShape>(&g.shape)) {
          for (int c = 0; c < 8; ++c)
            pts.push_back(g.origin * Eigen::Vector3d((c & 1 ? 0.5 : -0.5) * b->size.x(), (c & 2 ? 0.5 : -0.5) * b->size.y(),
                                                     (c & 4 ? 0.5 : -0.5) * b->size.z()));
        }
      }
    }
    model_points_.push_back(std::move(pts));
  }
}

void FrameView::reloadFrame() {
  error_.clear();
  perception::VideoReader* video = doc_->media()->video();
  const int frame = doc_->currentFrame();
  if (!video) {
    image_ = QImage();
    image_frame_ = -1;
  } else if (frame != image_frame_) {
    try {
      const cv::Mat bgr = video->frame(std::clamp(frame, 0, video->frame_count() - 1));
      image_ = QImage(bgr.data, bgr.cols, bgr.rows, int(bgr.step), QImage::Format_BGR888).copy();
      image_frame_ = frame;
      markers_.clear();
      if (show_markers_) {
        if (!detector_) {
          const perception::Camera* cam = doc_->media()->camera();
          detector_ = std::make_unique<perception::MarkerDetector>(cam && cam->board ? cam->board->dictionary
                                                                                     : std::string("DICT_4X4_100"));
        }
        for (const auto& m : detector_->detect(bgr)) {
          QPolygonF poly;
          for (const auto& c : m.corners) poly << QPointF(c.x, c.y);
          markers_.push_back({m.id, poly});
        }
      }
    } catch (const std::exception& e) {
      image_ = QImage();
      image_frame_ = -1;
      error_ = QString::fromUtf8(e.what());
    }
  }
  computeOverlay();
  update();
}

void FrameView::computeOverlay() {
  outlines_.assign(model_points_.size(), QPolygonF());
  start_poses_.update(*doc_, show_outlines_ && !image_.isNull());
  if (start_poses_.shown()) return;  // one outline a part: where it starts
  const perception::Camera* cam = doc_->media()->camera();
  if (!doc_->hasProject() || !cam || !cam->world_T_camera || !show_outlines_) return;
  const Pose camera_T_world = cam->world_T_camera->inverse();
  const int frame = doc_->currentFrame();
  const PoseList poses = doc_->demoPosesAt(frame);
  const Demonstration& demo = doc_->demonstration();
  for (size_t o = 0; o < model_points_.size() && o < poses.size(); ++o) {
    // In the hand between its grasp and its release the part's pose is not known (the 3D view
    // interpolates it); an outline there would look wrong without being wrong.
    bool at_event = false;
    for (const auto& e : demo.events) at_event |= e.frame == frame && e.object == int(o);
    if (!at_event && held_at_frame(demo, int(o), frame)) continue;
    std::vector<cv::Point2f> pts;
    pts.reserve(model_points_[o].size());
    const Pose T = camera_T_world * poses[o];
    for (const auto& p : model_points_[o]) {
      const Eigen::Vector3d pc = T * p;
      if (pc.z() <= 0.01) continue;
      const cv::Point2d px = cam->project(pc);
      pts.emplace_back(float(px.x), float(px.y));
    }
    if (pts.size() < 3) continue;
    std::vector<cv::Point2f> hull;
    cv::convexHull(pts, hull);
    QPolygonF poly;
    for (const auto& h : hull) poly << QPointF(h.x, h.y);
    outlines_[o] = poly;
  }
}

void FrameView::paintEvent(QPaintEvent*) {
  QPainter p(this);
  p.fillRect(rect(), QColor(0x20, 0x22, 0x25));
  p.setRenderHint(QPainter::Antialiasing);
  if (!doc_->hasProject()) return;
  QSizeF size = image_.isNull() ? QSizeF(doc_->media()->camera() ? doc_->media()->camera()->image_size.width : 1280,
                                         doc_->media()->camera() ? doc_->media()->camera()->image_size.height : 720)
                                : QSizeF(image_.size());
  const double s = std::min(width() / size.width(), height() / size.height());
  const QRectF target((width() - size.width() * s) / 2, (height() - size.height() * s) / 2, size.width() * s,
                      size.height() * s);
  if (!image_.isNull()) {
    p.setRenderHint(QPainter::SmoothPixmapTransform);
    p.drawImage(target, image_);
  } else {
    p.setPen(QColor(0xc8, 0xcc, 0xd0));
    const QString text = !error_.isEmpty()             ? error_
                         : !doc_->media()->videoError().isEmpty() ? doc_->media()->videoError()
                                                         : tr("No video.\nFile > Open Video… or drop a recording here.");
    p.drawText(rect().adjusted(12, 12, -12, -12), Qt::AlignCenter | Qt::TextWordWrap, text);
  }
  p.save();
  p.translate(target.topLeft());
  p.scale(s, s);
  const Demonstration& d = doc_->demonstration();
  std::vector<QRectF> labels;  // placed so far, to keep names from overlapping
  const bool start_poses = start_poses_.shown();
  const size_t parts = start_poses ? start_poses_.outlines().size() : outlines_.size();
  for (size_t o = 0; o < parts; ++o) {
    const bool selected = int(o) == doc_->selectedObject();
    QColor c;
    QRectF br;
    if (start_poses) {
      // The silhouette's edge, unfilled so the part's own edge in the video shows beside it; a
      // dark line under it keeps it visible on light and dark parts alike.
      const auto& pieces = start_poses_.outlines()[o];
      if (pieces.empty()) continue;
      c = objectColor(int(o)).lighter(130);
      const double width = selected ? 3.0 : 1.5;
      p.setBrush(Qt::NoBrush);
      p.setPen(QPen(QColor(0, 0, 0, 150), (width + 2.0) / s, Qt::SolidLine, Qt::RoundCap, Qt::RoundJoin));
      for (const QPolygonF& piece : pieces) p.drawPolyline(piece);
      p.setPen(QPen(c, width / s, Qt::SolidLine, Qt::RoundCap, Qt::RoundJoin));
      for (const QPolygonF& piece : pieces) p.drawPolyline(piece);
      br = start_poses_.bounds(int(o));
    } else {
      if (outlines_[o].isEmpty()) continue;
      c = selected ? kSelectionColor : objectColor(int(o)).lighter(130);
      p.setPen(QPen(c, (selected ? 3.0 : 2.0) / s));
      QColor fill = c;
      fill.setAlphaF(selected ? 0.18f : 0.08f);
      p.setBrush(fill);
      p.drawPolygon(outlines_[o]);
      br = outlines_[o].boundingRect();
    }
    if (o >= d.object_ids.size()) continue;
    QFont f = font();
    f.setPointSizeF(f.pointSizeF() / s);
    f.setBold(true);
    p.setFont(f);
    const QString name = QString::fromStdString(d.object_ids[o]);
    QRectF label(br.left(), br.top() - p.fontMetrics().height() - 2 / s, p.fontMetrics().horizontalAdvance(name),
                 p.fontMetrics().height());
    for (int tries = 0; tries < 4; ++tries) {
      bool clash = false;
      for (const QRectF& other : labels) clash |= other.intersects(label);
      if (!clash) break;
      label.translate(0, -label.height());
    }
    labels.push_back(label);
    p.setPen(c);
    p.drawText(label, Qt::AlignLeft | Qt::AlignVCenter, name);
  }
  for (const auto& m : markers_) {
    p.setPen(QPen(QColor(0x00, 0xe5, 0xff), 1.5 / s));
    p.setBrush(Qt::NoBrush);
    p.drawPolygon(m.corners);
    QFont f = font();
    f.setPointSizeF(f.pointSizeF() * 0.8 / s);
    p.setFont(f);
    p.drawText(m.corners.boundingRect().center(), QString::number(m.id));
  }
  p.restore();
  // The event at this frame, if any.
  QStringList here;
  for (const auto& e : d.events)
    if (e.frame == doc_->currentFrame())
      here << QStringLiteral("%1 %2").arg(eventTypeName(e.type), QString::fromStdString(d.object_ids[e.object]));
  if (!here.isEmpty()) {
    const QString text = here.join(QStringLiteral(", "));
    QFont f = font();
    f.setBold(true);
    p.setFont(f);
    const QRectF box(target.left() + 8, target.top() + 8, p.fontMetrics().horizontalAdvance(text) + 16, p.fontMetrics().height() + 8);
    p.setPen(Qt::NoPen);
    p.setBrush(QColor(0, 0, 0, 160));
    p.drawRoundedRect(box, 4, 4);
    p.setPen(Qt::white);
    p.drawText(box, Qt::AlignCenter, text);
  }
  if (!start_poses_.caption().isEmpty()) {
    QFont f = font();
    f.setBold(true);
    p.setFont(f);
    const QString text = p.fontMetrics().elidedText(start_poses_.caption(), Qt::ElideMiddle, int(target.width()) - 32);
    const QRectF box(target.left() + 8, target.bottom() - p.fontMetrics().height() - 16,
                     p.fontMetrics().horizontalAdvance(text) + 16, p.fontMetrics().height() + 8);
    p.setPen(Qt::NoPen);
    p.setBrush(QColor(0, 0, 0, 160));
    p.drawRoundedRect(box, 4, 4);
    p.setPen(Qt::white);
    p.drawText(box, Qt::AlignCenter, text);
  }
  const perception::Camera* cam = doc_->media()->camera();
  if (!image_.isNull() && (!cam || !cam->world_T_camera)) {
    p.setPen(QColor(0xff, 0xd0, 0x60));
    p.drawText(target.adjusted(8, 0, -8, -6), Qt::AlignBottom | Qt::AlignLeft,
               tr("No calibrated camera: outlines are not drawn (File > Open Camera…)"));
  }
}

// ---------------------------------------------------------------------------- VideoPanel

VideoPanel::VideoPanel(Document* doc, Transport* transport, QWidget* parent)
    : QWidget(parent), doc_(doc), transport_(transport) {
  setAcceptDrops(true);
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  layout->setSpacing(2);
  view_ = new FrameView(doc, this);
  layout->addWidget(view_, 1);
  auto* bar = new QHBoxLayout;
  bar->setContentsMargins(4, 0, 4, 2);
  auto button = [&](QStyle::StandardPixmap icon, const QString& tip, auto slot) {
    auto* b = new QToolButton(this);
    b->setIcon(style()->standardIcon(icon));
    b->setToolTip(tip);
    b->setAutoRaise(true);
    connect(b, &QToolButton::clicked, transport_, slot);
    bar->addWidget(b);
    return b;
  };
  button(QStyle::SP_MediaSkipBackward, tr("First frame (Home)"), &Transport::home);
  button(QStyle::SP_MediaSeekBackward, tr("One frame back (←); one second: Shift+←"), [this] { transport_->stepFrames(-1); });
  play_ = button(QStyle::SP_MediaPlay, tr("Play or pause (Space); J/K/L: backward, pause, forward"), &Transport::toggle);
  button(QStyle::SP_MediaSeekForward, tr("One frame forward (→); one second: Shift+→"), [this] { transport_->stepFrames(1); });
  button(QStyle::SP_MediaSkipForward, tr("Last frame (End)"), &Transport::end);
  slider_ = new QSlider(Qt::Horizontal, this);
  slider_->setToolTip(tr("Scrub through the recording"));
  bar->addWidget(slider_, 1);
  position_ = new QLabel(this);
  position_->setMinimumWidth(130);
  bar->addWidget(position_);
  auto* outlines = new QCheckBox(tr("Outlines"), this);
  outlines->setChecked(true);
  outlines->setToolTip(tr("Draw each part's model at its demonstrated pose through the calibrated camera; on the start frame of the part-model tracker, its silhouette where the tracker starts it"));
  connect(outlines, &QCheckBox::toggled, view_, &FrameView::setShowOutlines);
  bar->addWidget(outlines);
  auto* markers = new QCheckBox(tr("Markers"), this);
  markers->setToolTip(tr("Find and draw the ArUco markers in the frame"));
  connect(markers, &QCheckBox::toggled, view_, &FrameView::setShowMarkers);
  bar->addWidget(markers);
  layout->addLayout(bar);

  connect(slider_, &QSlider::valueChanged, this, [this](int v) {
    transport_->pause();
    doc_->setCurrentFrame(v);
  });
  connect(doc_, &Document::currentFrameChanged, this, &VideoPanel::refresh);
  connect(doc_->media(), &Media::videoChanged, this, &VideoPanel::refresh);
  connect(doc_, &Document::projectLoaded, this, &VideoPanel::refresh);
  connect(transport_, &Transport::stateChanged, this, [this](bool playing, double) {
    play_->setIcon(style()->standardIcon(playing ? QStyle::SP_MediaPause : QStyle::SP_MediaPlay));
  });
  refresh();
}

void VideoPanel::refresh() {
  QSignalBlocker b(slider_);
  slider_->setRange(0, std::max(0, doc_->frameCount() - 1));
  slider_->setValue(doc_->currentFrame());
  slider_->setEnabled(doc_->hasProject());
  if (doc_->hasProject())
    position_->setText(tr("frame %1/%2 · %3 s")
                           .arg(doc_->currentFrame())
                           .arg(doc_->frameCount() - 1)
                           .arg(doc_->currentFrame() / doc_->fps(), 0, 'f', 2));
  else
    position_->clear();
}

void VideoPanel::dragEnterEvent(QDragEnterEvent* e) {
  if (!e->mimeData()->hasUrls()) return;
  for (const QUrl& u : e->mimeData()->urls())
    if (u.isLocalFile() && isVideoFile(u.toLocalFile())) {
      e->acceptProposedAction();
      return;
    }
}

void VideoPanel::dropEvent(QDropEvent* e) {
  for (const QUrl& u : e->mimeData()->urls())
    if (u.isLocalFile() && isVideoFile(u.toLocalFile()) && doc_->hasProject()) {
      doc_->setMediaFile(Media::File::Video, u.toLocalFile());
      e->acceptProposedAction();
      return;
    }
}

}  // namespace demoplan::ui
