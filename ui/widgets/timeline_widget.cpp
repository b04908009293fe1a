#include "ui/widgets/timeline_widget.h"

#include <QComboBox>
#include <QContextMenuEvent>
#include <QHelpEvent>
#include <QLabel>
#include <QMenu>
#include <QMouseEvent>
#include <QPainter>
#include <QPainterPath>
#include <QProgressBar>
#include <QPushButton>
#include <QToolTip>
#include <QVBoxLayout>
#include <cmath>

#include "ui/document/demo_poses.h"
#include "ui/widgets/style.h"

namespace demoplan::ui {

TimelineWidget::TimelineWidget(Document* doc, QWidget* parent) : QWidget(parent), doc_(doc) {
  setMouseTracking(true);
  setFocusPolicy(Qt::ClickFocus);
  setMinimumHeight(kRuler + 2 * kLane + 8);
  setAccessibleName(tr("Event timeline"));
  auto repaint = [this] { update(); };
  connect(doc_, &Document::demonstrationChanged, this, repaint);
  connect(doc_, &Document::selectionChanged, this, repaint);
  connect(doc_, &Document::currentFrameChanged, this, repaint);
  connect(doc_, &Document::correctionsChanged, this, repaint);
  connect(doc_->media(), &Media::videoChanged, this, repaint);
  connect(doc_, &Document::projectLoaded, this, [this] {
    updateGeometry();
    update();
  });
}

QSize TimelineWidget::sizeHint() const {
  const int lanes = doc_->hasProject() ? int(doc_->demonstration().object_ids.size()) : 2;
  return {800, kRuler + std::max(2, lanes) * kLane + 8};
}
QSize TimelineWidget::minimumSizeHint() const { return {300, kRuler + 2 * kLane + 8}; }

FrameAxis TimelineWidget::axis() const { return {double(width()), doc_->frameCount()}; }
double TimelineWidget::right() const { return axis().right(); }
double TimelineWidget::frameToX(double frame) const { return axis().toX(frame); }
int TimelineWidget::xToFrame(double x) const { return axis().toFrame(x); }

int TimelineWidget::laneTop(int object) const { return kRuler + object * kLane; }

int TimelineWidget::laneAt(double y) const {
  if (!doc_->hasProject() || y < kRuler) return -1;
  const int lane = int((y - kRuler) / kLane);
  return lane < int(doc_->demonstration().object_ids.size()) ? lane : -1;
}

QRectF TimelineWidget::markerRect(int event) const {
  const auto& events = doc_->demonstration().events;
  if (event < 0 || event >= int(events.size())) return {};
  const ContactEvent& e = events[event];
  const int frame = drag_ == Drag::Event && drag_event_ == event ? drag_frame_ : e.frame;
  const double x = frameToX(frame);
  const double cy = laneTop(e.object) + kLane / 2.0;
  return QRectF(x - 8, cy - 8, 16, 16);
}

QRectF TimelineWidget::doubtRect(int index) const {
  const auto& doubts = doc_->demonstration().doubts;
  if (index < 0 || index >= int(doubts.size())) return {};
  const DetectionDoubt& x = doubts[size_t(index)];
  const double left = frameToX(x.first_frame);
  return QRectF(QPointF(left, laneTop(x.object) + 3), QPointF(std::max(frameToX(x.last_frame), left + 4), laneTop(x.object) + kLane - 3));
}

int TimelineWidget::doubtAt(const QPointF& p) const {
  if (!doc_->hasProject()) return -1;
  for (int i = 0; i < int(doc_->demonstration().doubts.size()); ++i)
    if (doubtRect(i).adjusted(-2, 0, 2, 0).contains(p)) return i;
  return -1;
}

QRectF TimelineWidget::correctionRect(int index) const {
  const auto& placed = doc_->corrections();
  if (index < 0 || index >= int(placed.size())) return {};
  const int lane = doc_->demonstration().object_index(placed[size_t(index)].id);
  if (lane < 0) return {};
  // Low in the lane, under the event markers at the same frame.
  return QRectF(frameToX(placed[size_t(index)].frame) - 5, laneTop(lane) + kLane - 11, 10, 10);
}

int TimelineWidget::correctionAt(const QPointF& p) const {
  if (!doc_->hasProject()) return -1;
  for (int i = 0; i < int(doc_->corrections().size()); ++i)
    if (correctionRect(i).adjusted(-2, -2, 2, 2).contains(p)) return i;
  return -1;
}

int TimelineWidget::eventAt(const QPointF& p) const {
  if (!doc_->hasProject()) return -1;
  const auto& events = doc_->demonstration().events;
  int best = -1;
  double best_d = 1e9;
  for (int i = 0; i < int(events.size()); ++i) {
    const QRectF r = markerRect(i).adjusted(-3, -3, 3, 3);
    if (!r.contains(p)) continue;
    const double d = std::abs(r.center().x() - p.x());
    if (d < best_d) best = i, best_d = d;
  }
  return best;
}

void TimelineWidget::paintMarker(QPainter& p, int event, double x, bool ghost) const {
  const Demonstration& d = doc_->demonstration();
  const ContactEvent& e = d.events[event];
  const double cy = laneTop(e.object) + kLane / 2.0;
  const double s = 7.5;
  QPainterPath tri;
  if (e.type == EventType::Grasp) {  // pointing up
    tri.moveTo(x, cy - s);
    tri.lineTo(x + s, cy + s * 0.8);
    tri.lineTo(x - s, cy + s * 0.8);
  } else {  // pointing down
    tri.moveTo(x, cy + s);
    tri.lineTo(x + s, cy - s * 0.8);
    tri.lineTo(x - s, cy - s * 0.8);
  }
  tri.closeSubpath();
  QColor fill = eventColor(e.type);
  const bool low = e.confidence < kLowConfidence;
  bool broken = false;
  for (const auto& issue : doc_->issues()) broken |= issue.event == event;
  if (ghost) fill.setAlphaF(0.45f);
  else fill.setAlphaF(float(0.35 + 0.65 * std::clamp(e.confidence, 0.0, 1.0)));
  if (low && !ghost) {  // a halo that asks for a look
    p.setPen(Qt::NoPen);
    QColor halo = kWarningColor;
    halo.setAlphaF(0.35f);
    p.setBrush(halo);
    p.drawEllipse(QPointF(x, cy), s + 5, s + 5);
  }
  if (broken && !ghost) {
    p.setPen(QPen(kErrorColor, 2));
    p.setBrush(Qt::NoBrush);
    p.drawEllipse(QPointF(x, cy), s + 4, s + 4);
  }
  const bool selected = event == doc_->selectedEvent();
  p.setPen(QPen(selected ? QColor(0x10, 0x10, 0x10) : eventColor(e.type).darker(140), selected ? 2.2 : 1.0,
                low ? Qt::DashLine : Qt::SolidLine));
  p.setBrush(fill);
  p.drawPath(tri);
  if (e.confidence < 0.995 || ghost) {
    QFont f = font();
    f.setPointSizeF(f.pointSizeF() * 0.75);
    p.setFont(f);
    p.setPen(low ? kWarningColor.darker(130) : palette().color(QPalette::Text));
    const QString label = ghost ? QString::number(drag_frame_) : QStringLiteral("%1%").arg(int(std::lround(e.confidence * 100)));
    p.drawText(QRectF(x + s + 1, cy - 8, 40, 16), Qt::AlignLeft | Qt::AlignVCenter, label);
  }
}

void TimelineWidget::paintEvent(QPaintEvent*) {
  QPainter p(this);
  p.setRenderHint(QPainter::Antialiasing);
  const QPalette pal = palette();
  p.fillRect(rect(), pal.color(QPalette::Base));
  if (!doc_->hasProject()) {
    p.setPen(pal.color(QPalette::PlaceholderText));
    p.drawText(rect(), Qt::AlignCenter, tr("No project: File > Open or File > New from Benchmark"));
    return;
  }
  const Demonstration& d = doc_->demonstration();
  const int n = doc_->frameCount();
  const double fps = doc_->fps();
  const int lanes = int(d.object_ids.size());
  // Ruler: a tick per second, a label every few seconds so labels do not collide.
  p.fillRect(QRectF(0, 0, width(), kRuler), pal.color(QPalette::Window));
  p.setPen(pal.color(QPalette::Mid));
  p.drawLine(QPointF(0, kRuler - 0.5), QPointF(width(), kRuler - 0.5));
  const double seconds = n / fps;
  const double px_per_s = (right() - kGutter - 8) / std::max(1e-9, seconds);
  int label_every = 1;
  while (label_every * px_per_s < 48) label_every *= 2;
  QFont small = font();
  small.setPointSizeF(small.pointSizeF() * 0.8);
  p.setFont(small);
  for (int s = 0; s <= int(seconds); ++s) {
    const double x = frameToX(s * fps);
    const bool labelled = s % label_every == 0;
    p.setPen(pal.color(QPalette::Mid));
    p.drawLine(QPointF(x, kRuler - (labelled ? 8 : 4)), QPointF(x, kRuler));
    if (labelled) {
      p.setPen(pal.color(QPalette::WindowText));
      p.drawText(QRectF(x + 2, 0, 60, kRuler - 6), Qt::AlignLeft | Qt::AlignVCenter, QStringLiteral("%1 s").arg(s));
    }
  }
  // Lanes.
  p.setFont(font());
  for (int o = 0; o < lanes; ++o) {
    const QRectF lane(0, laneTop(o), width(), kLane);
    if (o % 2) p.fillRect(lane, pal.color(QPalette::AlternateBase));
    if (o == doc_->selectedObject()) {
      QColor sel = kSelectionColor;
      sel.setAlphaF(0.12f);
      p.fillRect(lane, sel);
    }
    p.setPen(Qt::NoPen);
    p.setBrush(objectColor(o));
    p.drawRoundedRect(QRectF(8, lane.center().y() - 5, 10, 10), 2, 2);
    p.setPen(pal.color(QPalette::Text));
    p.drawText(QRectF(24, lane.top(), kGutter - 28, kLane), Qt::AlignVCenter | Qt::AlignLeft,
               p.fontMetrics().elidedText(QString::fromStdString(d.object_ids[o]), Qt::ElideRight, kGutter - 28));
  }
  p.setPen(pal.color(QPalette::Mid));
  p.drawLine(QPointF(kGutter, kRuler), QPointF(kGutter, laneTop(lanes)));
  // Doubts: the frames the detection could not decide, hatched amber (as in the part tracks).
  for (int i = 0; i < int(d.doubts.size()); ++i) {
    const QRectF r = doubtRect(i);
    QColor hatch = kDoubtColor;
    hatch.setAlphaF(0.8f);
    p.fillRect(r, QBrush(hatch, Qt::FDiagPattern));
    p.setPen(QPen(kDoubtColor.darker(115), 1.2));
    p.setBrush(Qt::NoBrush);
    p.drawRect(r);
  }
  // Carrying intervals: from a grasp to the next release of the same part.
  for (size_t i = 0; i < d.events.size(); ++i) {
    const ContactEvent& g = d.events[i];
    if (g.type != EventType::Grasp) continue;
    for (size_t j = i + 1; j < d.events.size(); ++j) {
      if (d.events[j].object != g.object) continue;
      if (d.events[j].type == EventType::Release) {
        QColor c = objectColor(g.object);
        c.setAlphaF(0.28f);
        const double y = laneTop(g.object) + kLane / 2.0;
        p.fillRect(QRectF(frameToX(g.frame), y - 3, frameToX(d.events[j].frame) - frameToX(g.frame), 6), c);
      }
      break;
    }
  }
  // Parts placed again for the part-model tracker: a diamond in the part's colour.
  for (int i = 0; i < int(doc_->corrections().size()); ++i) {
    const QRectF r = correctionRect(i);
    if (!r.isEmpty()) paintPlacementMark(p, r, d.object_index(doc_->corrections()[size_t(i)].id), pal.color(QPalette::Text));
  }
  // Markers, the one being dragged as a ghost at its new frame.
  for (int i = 0; i < int(d.events.size()); ++i) {
    if (drag_ == Drag::Event && drag_event_ == i && drag_moved_) {
      paintMarker(p, i, frameToX(d.events[i].frame), false);
      paintMarker(p, i, frameToX(drag_frame_), true);
    } else {
      paintMarker(p, i, frameToX(d.events[i].frame), false);
    }
  }
  // Playhead.
  const double x = frameToX(doc_->currentFrame());
  p.setPen(QPen(kBusyColor, 1.5));
  p.drawLine(QPointF(x, 2), QPointF(x, height()));
  QPainterPath head;
  head.moveTo(x - 6, 2);
  head.lineTo(x + 6, 2);
  head.lineTo(x, 10);
  head.closeSubpath();
  p.setPen(Qt::NoPen);
  p.setBrush(kBusyColor);
  p.drawPath(head);
}

void TimelineWidget::mousePressEvent(QMouseEvent* e) {
  if (!doc_->hasProject() || e->button() != Qt::LeftButton) return;
  press_pos_ = e->position();
  drag_moved_ = false;
  const int ev = eventAt(e->position());
  if (ev >= 0) {
    doc_->selectEvent(ev);
    drag_ = Drag::Event;
    drag_event_ = ev;
    drag_frame_ = doc_->demonstration().events[ev].frame;
    return;
  }
  if (const int c = correctionAt(e->position()); c >= 0) {
    const PartCorrection& placed = doc_->corrections()[size_t(c)];
    doc_->selectObject(doc_->demonstration().object_index(placed.id));
    doc_->setCurrentFrame(placed.frame);
    return;
  }
  const int lane = laneAt(e->position().y());
  if (lane >= 0 && e->position().x() < kGutter) {
    doc_->selectObject(lane);
    return;
  }
  if (e->position().x() >= kGutter) {
    drag_ = Drag::Playhead;
    doc_->setCurrentFrame(xToFrame(e->position().x()));
    if (lane >= 0) doc_->selectObject(lane);
  }
}

void TimelineWidget::mouseMoveEvent(QMouseEvent* e) {
  if (drag_ == Drag::Playhead) {
    doc_->setCurrentFrame(xToFrame(e->position().x()));
  } else if (drag_ == Drag::Event) {
    if (!drag_moved_ && std::abs(e->position().x() - press_pos_.x()) < 3) return;
    drag_moved_ = true;
    drag_frame_ = xToFrame(e->position().x());
    update();
  } else {
    const int ev = eventAt(e->position());
    setCursor(ev >= 0 ? Qt::SizeHorCursor : Qt::ArrowCursor);
  }
}

void TimelineWidget::mouseReleaseEvent(QMouseEvent* e) {
  if (drag_ == Drag::Event && drag_moved_ && drag_event_ >= 0) {
    const int ev = drag_event_, frame = drag_frame_;
    drag_ = Drag::None;
    drag_event_ = -1;
    doc_->moveEvent(ev, frame);
    if (doc_->selectedEvent() >= 0) doc_->setCurrentFrame(frame);
  }
  drag_ = Drag::None;
  drag_event_ = -1;
  update();
}

void TimelineWidget::mouseDoubleClickEvent(QMouseEvent* e) {
  const int lane = laneAt(e->position().y());
  if (lane < 0 || e->position().x() < kGutter || eventAt(e->position()) >= 0) return;
  const int frame = xToFrame(e->position().x());
  // The event that keeps the lane's grasps and releases alternating at this point.
  const EventType type = held_at_frame(doc_->demonstration(), lane, frame) ? EventType::Release : EventType::Grasp;
  doc_->selectEvent(doc_->addEvent(frame, lane, type));
}

void TimelineWidget::contextMenuEvent(QContextMenuEvent* e) {
  if (!doc_->hasProject()) return;
  const int ev = eventAt(e->pos());
  const int lane = laneAt(e->pos().y());
  const int frame = xToFrame(e->pos().x());
  QMenu menu(this);
  const Demonstration& d = doc_->demonstration();
  if (ev >= 0) {
    doc_->selectEvent(ev);
    const ContactEvent& ce = d.events[ev];
    menu.addAction(tr("Delete %1 of %2").arg(eventTypeName(ce.type), QString::fromStdString(d.object_ids[ce.object])),
                   this, [this, ev] { doc_->removeEvent(ev); });
    if (ce.confidence < 1.0)
      menu.addAction(tr("Mark as checked (confidence 100%)"), this, [this, ev] { doc_->setEventConfidence(ev, 1.0); });
  } else if (const int c = correctionAt(e->pos()); c >= 0) {
    const PartCorrection& placed = doc_->corrections()[size_t(c)];
    menu.addAction(tr("Remove the placement of %1 at frame %2").arg(QString::fromStdString(placed.id)).arg(placed.frame),
                   this, [this, c] { doc_->removeCorrection(c); });
  } else if (const int doubt = doubtAt(e->pos()); doubt >= 0) {
    menu.addAction(tr("Dismiss This Doubt (checked)"), this, [this, doubt] { doc_->removeDoubt(doubt); });
  }
  if (ev < 0 && lane >= 0) {
    if (!menu.isEmpty()) menu.addSeparator();
    const QString name = QString::fromStdString(d.object_ids[lane]);
    menu.addAction(tr("Add grasp of %1 at frame %2").arg(name).arg(frame), this,
                   [this, frame, lane] { doc_->selectEvent(doc_->addEvent(frame, lane, EventType::Grasp)); });
    menu.addAction(tr("Add release of %1 at frame %2").arg(name).arg(frame), this,
                   [this, frame, lane] { doc_->selectEvent(doc_->addEvent(frame, lane, EventType::Release)); });
    if (frame > 0 && doc_->correctionAt(lane, frame) < 0)
      menu.addAction(tr("Place %1 again at frame %2 (part models)").arg(name).arg(frame), this, [this, frame, lane] {
        doc_->selectObject(lane);
        doc_->setCurrentFrame(frame);
        doc_->placeAgain(lane);
      });
  }
  if (!menu.isEmpty()) menu.exec(e->globalPos());
}

bool TimelineWidget::event(QEvent* e) {
  if (e->type() == QEvent::ToolTip && doc_->hasProject()) {
    auto* he = static_cast<QHelpEvent*>(e);
    const int ev = eventAt(he->pos());
    if (ev >= 0) {
      const Demonstration& d = doc_->demonstration();
      const ContactEvent& ce = d.events[ev];
      QString tip = tr("<b>%1 of %2</b><br>%3<br>confidence %4%")
                        .arg(eventTypeName(ce.type), QString::fromStdString(d.object_ids[ce.object]),
                             frameText(ce.frame, doc_->fps()))
                        .arg(int(std::lround(ce.confidence * 100)));
      for (const auto& issue : doc_->issues())
        if (issue.event == ev)
          tip += QStringLiteral("<br><span style='color:#cf222e'>%1</span>").arg(QString::fromStdString(issue.message).toHtmlEscaped());
      tip += tr("<br><i>drag to move · right-click to delete</i>");
      QToolTip::showText(he->globalPos(), tip, this, markerRect(ev).toRect());
    } else if (const int c = correctionAt(he->pos()); c >= 0) {
      const PartCorrection& placed = doc_->corrections()[size_t(c)];
      const QString tip = tr("<b>%1 placed again</b> at %2<br>Detect Events with the part models follows it from this "
                             "pose<br><i>click to show it over the video · right-click to remove</i>")
                              .arg(QString::fromStdString(placed.id), frameText(placed.frame, doc_->fps()));
      QToolTip::showText(he->globalPos(), tip, this, correctionRect(c).toRect());
    } else if (const int doubt = doubtAt(he->pos()); doubt >= 0) {
      const DetectionDoubt& x = doc_->demonstration().doubts[size_t(doubt)];
      const QString tip = tr("<b>Detection doubt</b>, frames %1–%2<br>%3<br><i>check the events here · right-click to "
                             "dismiss</i>")
                              .arg(x.first_frame)
                              .arg(x.last_frame)
                              .arg(QString::fromStdString(x.message).toHtmlEscaped());
      QToolTip::showText(he->globalPos(), tip, this, doubtRect(doubt).toRect());
    } else {
      QToolTip::hideText();
    }
    return true;
  }
  return QWidget::event(e);
}

// ------------------------------------------------------------------------ TimelinePanel

TimelinePanel::TimelinePanel(Document* doc, QWidget* parent) : QWidget(parent), doc_(doc) {
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  layout->setSpacing(2);
  // Event detection: run perception on the video, with progress and cancel.
  auto* bar = new QHBoxLayout;
  bar->setContentsMargins(6, 2, 6, 0);
  detect_ = new QPushButton(tr("Detect Events in the Video"), this);
  detect_->setToolTip(tr("Find the grasps and releases and the parts' poses in the video (markers on the parts, "
                         "hand near a part). Replaces the events; Undo brings them back."));
  tracker_ = new QComboBox(this);
  tracker_->addItem(tr("Markers on the parts"));
  tracker_->addItem(tr("Part models (no markers)"));
  tracker_->setToolTip(tr("How the parts are followed through the video: by the markers stuck on them, or by their "
                          "3D models from where they stand in the first frame (init.json beside the marker scene, "
                          "else the parts' poses at frame 0 in this project: at frame 0 the video shows their "
                          "outlines; move a part in the 3D view until its outline lies on it)"));
  tracker_->setCurrentIndex(doc_->detection()->modelTracker() ? 1 : 0);
  connect(tracker_, &QComboBox::currentIndexChanged, this,
          [this](int index) { doc_->detection()->setModelTracker(index == 1); });
  connect(doc_->detection(), &EventDetection::trackerChanged, this,
          [this](bool model) { tracker_->setCurrentIndex(model ? 1 : 0); });
  cancel_ = new QPushButton(tr("Cancel"), this);
  progress_ = new QProgressBar(this);
  progress_->setMaximumWidth(220);
  progress_->setTextVisible(true);
  detection_ = new QLabel(this);
  detection_->setWordWrap(false);
  bar->addWidget(detect_);
  bar->addWidget(tracker_);
  bar->addWidget(progress_);
  bar->addWidget(cancel_);
  bar->addWidget(detection_, 1);
  layout->addLayout(bar);
  // What the detection warns of (a part's start the video does not bear out): on a line of its
  // own under the bar, as the status beside the button has no room for it.
  warnings_ = new QLabel(this);
  warnings_->setWordWrap(true);
  warnings_->setContentsMargins(8, 0, 8, 2);
  warnings_->setVisible(false);
  layout->addWidget(warnings_);
  connect(detect_, &QPushButton::clicked, this, [this] { doc_->detection()->start(); });
  connect(cancel_, &QPushButton::clicked, this, [this] { doc_->detection()->runner()->cancel(); });
  ExtractionRunner* ex = doc_->detection()->runner();
  connect(ex, &ExtractionRunner::started, this, [this] {
    progress_->setValue(0);
    detection_->setText(tr("Detecting…"));
    refreshDetection();
  });
  connect(ex, &ExtractionRunner::progress, this, [this](int done, int total) {
    progress_->setRange(0, total);
    progress_->setValue(done);
    progress_->setFormat(tr("frame %v of %m"));
  });
  connect(ex, &ExtractionRunner::cancelled, this, [this] {
    detection_->setText(tr("Detection cancelled: the events are unchanged."));
    refreshDetection();
  });
  connect(doc_->detection(), &EventDetection::done, this, [this](const ExtractionOutcome& o) {
    if (o.ok) {
      int low = 0;
      for (const auto& e : o.demonstration.events) low += e.confidence < kLowConfidence;
      QString text = tr("Found %1 events in %2 frames (%3 s). Check them, then the poses; Ctrl+Z brings the previous events back.")
                         .arg(o.demonstration.events.size())
                         .arg(o.frames)
                         .arg(o.seconds, 0, 'f', 1);
      detection_->setText(text);
      detection_->setToolTip(text);
      showDetectionWarnings(o.warnings);
    } else {
      detection_->setText(tr("<span style='color:%1'>Detection failed:</span> %2")
                              .arg(kErrorColor.name(), QString::fromStdString(o.error).toHtmlEscaped()));
      detection_->setToolTip(QString::fromStdString(o.error));
      showDetectionWarnings({});
    }
    refreshDetection();
  });
  connect(doc_->steps(), &StepStatusModel::changed, this, &TimelinePanel::refreshDetection);
  connect(doc_, &Document::projectLoaded, this, [this] {
    detection_->clear();
    showDetectionWarnings({});
    refreshDetection();
  });
  timeline_ = new TimelineWidget(doc, this);
  validity_ = new QLabel(this);
  validity_->setTextFormat(Qt::RichText);
  validity_->setWordWrap(true);
  validity_->setContentsMargins(8, 2, 8, 4);
  validity_->setTextInteractionFlags(Qt::LinksAccessibleByMouse | Qt::LinksAccessibleByKeyboard);
  layout->addWidget(timeline_, 1);
  layout->addWidget(validity_);
  connect(validity_, &QLabel::linkActivated, this, [this](const QString& link) {
    if (link.startsWith(QStringLiteral("issue:"))) jumpToIssue(link.mid(6).toInt());
    if (link.startsWith(QStringLiteral("doubt:"))) jumpToDoubt(link.mid(6).toInt());
  });
  connect(doc_, &Document::demonstrationChanged, this, &TimelinePanel::refresh);
  connect(doc_, &Document::projectLoaded, this, &TimelinePanel::refresh);
  refresh();
  refreshDetection();
}

void TimelinePanel::jumpToIssue(int index) {
  const auto& issues = doc_->issues();
  if (index < 0 || index >= int(issues.size())) return;
  if (issues[index].event >= 0) doc_->selectEvent(issues[index].event);
  timeline_->setFocus();
}

void TimelinePanel::jumpToDoubt(int index) {
  const auto& doubts = doc_->demonstration().doubts;
  if (index < 0 || index >= int(doubts.size())) return;
  doc_->selectEvent(-1);
  doc_->selectObject(doubts[size_t(index)].object);
  doc_->setCurrentFrame(doubts[size_t(index)].first_frame);
  timeline_->setFocus();
}

int TimelinePanel::jumpToNextDoubt() {
  const auto& doubts = doc_->demonstration().doubts;
  if (doubts.empty()) return -1;
  // The first one after the playhead, else the first of all (round and round with the key).
  int next = 0;
  for (int i = 0; i < int(doubts.size()); ++i)
    if (doubts[size_t(i)].first_frame > doc_->currentFrame()) {
      next = i;
      break;
    }
  jumpToDoubt(next);
  return next;
}

void TimelinePanel::showDetectionWarnings(const std::vector<std::string>& warnings) {
  warnings_->setVisible(!warnings.empty());
  if (warnings.empty()) return warnings_->clear();
  // The first in full, a count of the others; all of them on hover.
  QString text = tr("<span style='color:%1'>Warning:</span> %2")
                     .arg(kWarningColor.name(), QString::fromStdString(warnings.front()).toHtmlEscaped());
  if (warnings.size() > 1) text += tr(" (and %n more: hover here)", "", int(warnings.size()) - 1);
  QStringList all;
  for (const auto& w : warnings) all << QString::fromStdString(w);
  warnings_->setText(text);
  warnings_->setToolTip(all.join(QStringLiteral("\n")));
}

void TimelinePanel::refreshDetection() {
  const bool running = doc_->detection()->runner()->isRunning();
  const QString blocker = doc_->detection()->blocker();
  detect_->setEnabled(!running && blocker.isEmpty());
  tracker_->setEnabled(!running);
  detect_->setToolTip(blocker.isEmpty() || running ? tr("Find the grasps and releases and the parts' poses in the video "
                                                        "(markers on the parts, hand near a part). Replaces the events; "
                                                        "Undo brings them back.")
                                                   : blocker);
  cancel_->setVisible(running);
  progress_->setVisible(running);
}

void TimelinePanel::refresh() {
  if (!doc_->hasProject()) {
    validity_->clear();
    return;
  }
  const auto& issues = doc_->issues();
  // Doubts do not break a rule; they ask for a look, so they follow the verdict.
  QString doubts;
  const auto& dd = doc_->demonstration().doubts;
  if (!dd.empty())
    doubts = tr(" <span style='color:%1'>%2 detection doubt(s) to check:</span> <a href='doubt:0'>%3</a>%4")
                 .arg(kDoubtColor.darker(120).name())
                 .arg(dd.size())
                 .arg(QString::fromStdString(dd.front().message).toHtmlEscaped())
                 .arg(dd.size() > 1 ? tr(" (Ctrl+Shift+J: the next one)") : QString());
  if (issues.empty()) {
    int low = 0;
    for (const auto& e : doc_->demonstration().events) low += e.confidence < kLowConfidence;
    QString text = tr("<span style='color:%1'>&#10004;</span> Demonstration valid: %2 events on %3 parts.")
                       .arg(kOkColor.name())
                       .arg(doc_->demonstration().events.size())
                       .arg(doc_->demonstration().object_ids.size());
    if (low > 0)
      text += tr(" <span style='color:%1'>%2 event(s) have low confidence (dashed, amber halo): check them.</span>")
                  .arg(kWarningColor.darker(120).name())
                  .arg(low);
    validity_->setText(text + doubts);
    return;
  }
  QStringList parts;
  for (int i = 0; i < int(issues.size()) && i < 3; ++i) {
    const QString msg = QString::fromStdString(issues[i].message).toHtmlEscaped();
    parts << (issues[i].event >= 0 ? QStringLiteral("<a href='issue:%1'>%2</a>").arg(i).arg(msg) : msg);
  }
  QString text = tr("<span style='color:%1'>&#10008; The demonstration breaks a rule:</span> ").arg(kErrorColor.name()) +
                 parts.join(QStringLiteral(" · "));
  if (issues.size() > 3) text += tr(" (and %1 more)").arg(issues.size() - 3);
  validity_->setText(text + doubts);
}

}  // namespace demoplan::ui
