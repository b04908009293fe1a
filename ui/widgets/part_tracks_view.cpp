#include "ui/widgets/part_tracks_view.h"

#include <QHelpEvent>
#include <QMouseEvent>
#include <QPainter>
#include <QPainterPath>
#include <QToolTip>
#include <algorithm>
#include <cmath>
#include <limits>

#include <Eigen/Geometry>

#include "perception/events/tracks_demonstration.h"
#include "perception/tracking/track_coverage.h"
#include "plot/axis.h"
#include "plot/painter_canvas.h"
#include "plot/palette.h"
#include "ui/widgets/style.h"

namespace demoplan::ui {

namespace {

constexpr double kBandTop = 3, kBandH = 16, kConfidenceH = 4, kStripGap = 8, kBottom = 6;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
const QColor kRestShade{kTrackRestColor.red(), kTrackRestColor.green(), kTrackRestColor.blue(), 50};

// The range of a running median of `values` (NaN: unseen), and zero, the first rest: a few
// outliers of tens of centimetres must not flatten the curve the operator reads, so they leave
// the plot; a carry, many frames long, stays in it.
std::pair<double, double> robustRange(const std::vector<double>& values) {
  constexpr int kHalf = 2;
  double lo = 0, hi = 0;
  std::vector<double> window;
  for (int i = 0; i < int(values.size()); ++i) {
    window.clear();
    for (int j = std::max(0, i - kHalf); j <= std::min(int(values.size()) - 1, i + kHalf); ++j)
      if (!std::isnan(values[size_t(j)])) window.push_back(values[size_t(j)]);
    if (window.empty()) continue;
    std::nth_element(window.begin(), window.begin() + long(window.size() / 2), window.end());
    lo = std::min(lo, window[window.size() / 2]);
    hi = std::max(hi, window[window.size() / 2]);
  }
  const double pad = std::max(0.08 * (hi - lo), 1.0);
  return {lo - pad, hi + pad};
}

QString segmentName(const perception::TrackSegment& s) {
  switch (s.kind) {
    case perception::SegmentKind::Rest: return PartTracksView::tr("rest");
    case perception::SegmentKind::Carry:
      return PartTracksView::tr("carry %1 mm").arg(s.distance * 1000, 0, 'f', 0);
    case perception::SegmentKind::Ride: return PartTracksView::tr("ride %1 mm").arg(s.distance * 1000, 0, 'f', 0);
    case perception::SegmentKind::Moving: return PartTracksView::tr("moving, no carry");
  }
  return {};
}

}  // namespace

PartTracksView::PartTracksView(Document* doc, QWidget* parent) : QWidget(parent), doc_(doc) {
  setMouseTracking(true);
  setAccessibleName(tr("Part tracks"));
  auto repaint = [this] { update(); };
  connect(doc_, &Document::demonstrationChanged, this, repaint);
  connect(doc_, &Document::selectionChanged, this, repaint);
  connect(doc_, &Document::currentFrameChanged, this, repaint);
  connect(doc_, &Document::correctionsChanged, this, repaint);
  connect(doc_->trackDetection(), &TrackDetection::tracksChanged, this, &PartTracksView::reload);
}

QSize PartTracksView::sizeHint() const { return {800, 230}; }
// Small enough that the main window still fits a 1280x800 screen with the dock open.
QSize PartTracksView::minimumSizeHint() const { return {300, 64}; }

QRectF PartTracksView::segmentBand() const {
  const FrameAxis a = axis();
  return QRectF(QPointF(a.left(), kBandTop), QPointF(a.right(), kBandTop + kBandH));
}

bool PartTracksView::showsAngle() const { return height() >= kMinHeightWithAngle; }

QRectF PartTracksView::confidenceStrip() const {
  const FrameAxis a = axis();
  return QRectF(QPointF(a.left(), kBandTop + kBandH + 1), QPointF(a.right(), kBandTop + kBandH + 1 + kConfidenceH));
}

QRectF PartTracksView::positionPlot() const {
  const FrameAxis a = axis();
  const double top = confidenceStrip().bottom() + 3;
  const double room = height() - top - kBottom;
  // On a small screen the dock is short: the position alone, the angle in the tooltip.
  const double h = showsAngle() ? (room - kStripGap) * 0.62 : room;
  return QRectF(QPointF(a.left(), top), QPointF(a.right(), top + std::max(20.0, h)));
}

QRectF PartTracksView::anglePlot() const {
  if (!showsAngle()) return {};
  const FrameAxis a = axis();
  const double top = positionPlot().bottom() + kStripGap;
  return QRectF(QPointF(a.left(), top), QPointF(a.right(), height() - kBottom));
}

void PartTracksView::showEvent(QShowEvent* e) {
  QWidget::showEvent(e);
  if (!tracks_) reload();  // segmented on first sight, not when the project opens
}

void PartTracksView::setRow(int row) {
  if (row == row_) return;
  row_ = row;
  computeSeries();
  update();
}

void PartTracksView::reload() {
  tracks_ = isVisible() ? doc_->trackDetection()->tracks() : nullptr;
  if (tracks_ && row_ >= int(tracks_->tracks.object_ids.size())) row_ = -1;
  computeSeries();
  update();
  emit tracksReloaded();
}

void PartTracksView::computeSeries() {
  series_.clear();
  if (!tracks_ || row_ < 0 || row_ >= int(tracks_->tracks.samples.size())) return;
  const auto& samples = tracks_->tracks.samples[size_t(row_)];
  // The reference: the first rest's robust pose, else the first sample seen.
  Pose ref = Pose::Identity();
  bool have_ref = false;
  if (row_ < int(tracks_->segmentation.objects.size()))
    for (const auto& s : tracks_->segmentation.objects[size_t(row_)].segments)
      if (s.kind == perception::SegmentKind::Rest) {
        ref = s.pose;
        have_ref = true;
        break;
      }
  for (size_t f = 0; f < samples.size() && !have_ref; ++f)
    if (samples[f].valid) ref = samples[f].pose, have_ref = true;
  series_.assign(samples.size(), {kNaN, kNaN, kNaN, kNaN});
  confidence_.assign(samples.size(), kNaN);
  for (size_t f = 0; f < samples.size(); ++f) {
    if (!samples[f].valid) continue;
    confidence_[f] = samples[f].confidence;
    const Eigen::Vector3d d = (samples[f].pose.translation() - ref.translation()) * 1000.0;
    const double angle = Eigen::AngleAxisd(ref.linear().transpose() * samples[f].pose.linear()).angle() * 180.0 / M_PI;
    series_[f] = {d.x(), d.y(), d.z(), angle};
  }
  auto column = [&](int k) {
    std::vector<double> v(series_.size());
    for (size_t f = 0; f < series_.size(); ++f) v[f] = series_[f][size_t(k)];
    return v;
  };
  pos_lo_ = 0, pos_hi_ = 0;
  for (int k = 0; k < 3; ++k) {
    const auto [lo, hi] = robustRange(column(k));
    pos_lo_ = std::min(pos_lo_, lo), pos_hi_ = std::max(pos_hi_, hi);
  }
  std::tie(ang_lo_, ang_hi_) = robustRange(column(3));
}

int PartTracksView::segmentAt(int frame) const {
  if (!tracks_ || row_ < 0 || row_ >= int(tracks_->segmentation.objects.size())) return -1;
  const auto& segs = tracks_->segmentation.objects[size_t(row_)].segments;
  for (size_t i = 0; i < segs.size(); ++i)
    if (frame >= segs[i].first && frame <= segs[i].last) return int(i);
  return -1;
}

int PartTracksView::demonstrationObject() const {
  if (!tracks_ || row_ < 0 || !doc_->hasProject()) return -1;
  return doc_->demonstration().object_index(tracks_->tracks.object_ids[size_t(row_)]);
}

std::vector<PartTracksView::Doubt> PartTracksView::doubts() const {
  std::vector<Doubt> out;
  const int object = demonstrationObject();
  if (object >= 0) {
    // The demonstration's doubts: the operator dismisses them there, and they are saved.
    for (const auto& d : doc_->demonstration().doubts)
      if (d.object == object) out.push_back({d.first_frame, d.last_frame, QString::fromStdString(d.message)});
  } else if (tracks_) {
    // A part outside the plan (a tray) has no place in the demonstration: the detector's own.
    for (const auto& d : tracks_->segmentation.doubts)
      if (d.object == row_) out.push_back({d.first, d.last, QString::fromStdString(d.message)});
  }
  return out;
}

void PartTracksView::paintSegments(QPainter& p) const {
  const FrameAxis a = axis();
  const QRectF band = segmentBand();
  const double top = band.top(), bottom = showsAngle() ? anglePlot().bottom() : positionPlot().bottom();
  const QColor part = objectColor(demonstrationObject());
  QFont small = font();
  small.setPointSizeF(small.pointSizeF() * 0.8);
  p.setFont(small);
  if (row_ < int(tracks_->segmentation.objects.size()))
    for (const auto& s : tracks_->segmentation.objects[size_t(row_)].segments) {
      // Each segment covers its frames up to the start of the next one.
      const QRectF r(QPointF(a.toX(s.first), top), QPointF(a.toX(s.last + 1 < a.frames ? s.last + 1 : s.last), bottom));
      QBrush brush;
      switch (s.kind) {
        case perception::SegmentKind::Rest: brush = QBrush(kRestShade); break;
        case perception::SegmentKind::Carry: {
          QColor c = part;
          c.setAlphaF(0.22f);
          brush = QBrush(c);
          break;
        }
        case perception::SegmentKind::Ride: {
          QColor c = part;
          c.setAlphaF(0.45f);
          brush = QBrush(c, Qt::BDiagPattern);
          break;
        }
        case perception::SegmentKind::Moving: brush = QBrush(QColor(0x99, 0x99, 0x99, 110), Qt::Dense6Pattern); break;
      }
      p.fillRect(r, brush);
      // The band names the segment where it fits.
      p.setPen(QColor(0xff, 0xff, 0xff));
      p.drawLine(QPointF(r.left(), top), QPointF(r.left(), band.bottom()));
      const QString name = segmentName(s);
      if (p.fontMetrics().horizontalAdvance(name) + 6 < r.width()) {
        p.setPen(palette().color(QPalette::Text));
        p.drawText(QRectF(r.left(), top, r.width(), band.height()), Qt::AlignCenter, name);
      }
    }
  for (const Doubt& d : doubts()) {
    const QRectF r(QPointF(a.toX(d.first), top), QPointF(std::max(a.toX(d.last), a.toX(d.first) + 4), bottom));
    QColor hatch = kDoubtColor;
    hatch.setAlphaF(0.5f);  // lighter than in the timeline: the curves must stay readable
    p.fillRect(r, QBrush(hatch, Qt::FDiagPattern));
    p.setPen(QPen(kDoubtColor.darker(115), 1.2));
    p.setBrush(Qt::NoBrush);
    p.drawRect(r);
  }
}

QColor PartTracksView::confidenceColor(int frame) const {
  if (frame < 0 || frame >= int(confidence_.size())) return {};
  const double c = confidence_[size_t(frame)];
  if (std::isnan(c)) return kUnseenColor;
  return c < kLowConfidence ? kErrorColor : c < perception::kSureConfidence ? kWarningColor : kOkColor;
}

void PartTracksView::paintConfidence(QPainter& p) const {
  const FrameAxis a = axis();
  const QRectF strip = confidenceStrip();
  // One rectangle per run of frames of one colour, each frame up to the next one's x.
  for (int f = 0; f < int(confidence_.size());) {
    const QColor c = confidenceColor(f);
    int end = f + 1;
    while (end < int(confidence_.size()) && confidenceColor(end) == c) ++end;
    p.fillRect(QRectF(QPointF(a.toX(f), strip.top()), QPointF(a.toX(end < a.frames ? end : end - 1), strip.bottom())), c);
    f = end;
  }
}

void PartTracksView::paintStrip(QPainter& p, const QRectF& box, int first_series, int series, double lo, double hi,
                                const QString& title) const {
  plot::PainterCanvas canvas(p);
  const plot::Ticks ticks = plot::nice_ticks(lo, hi, box.height() > 70 ? 4 : 2);
  auto sy = [&](double v) { return box.bottom() - (v - lo) / (hi - lo) * box.height(); };
  for (double v : ticks.values) {
    if (v < lo || v > hi) continue;
    const double y = sy(v);
    canvas.line({box.left(), y}, {box.right(), y}, plot::Stroke{v == 0 ? QColor(0xaa, 0xaa, 0xaa) : plot::kGridColor, 1});
    canvas.text({box.left() - 5, y}, plot::tick_label(v, ticks.step),
                plot::TextStyle{.size = 9.5, .color = plot::kAxisColor, .align = Qt::AlignRight | Qt::AlignVCenter});
  }
  // A faint line per second, under the timeline's ruler ticks.
  const FrameAxis a = axis();
  for (int sec = 1; sec * doc_->fps() < a.frames; ++sec) {
    const double x = a.toX(sec * doc_->fps());
    canvas.line({x, box.top()}, {x, box.bottom()}, plot::Stroke{plot::kGridColor, 1});
  }
  // The strip's name and, for x, y, z, which colour is which.
  canvas.text({8, box.top()}, title, plot::TextStyle{.size = 10.5, .bold = true, .align = Qt::AlignLeft | Qt::AlignTop});
  if (series > 1)
    for (int k = 0; k < series; ++k)
      canvas.text({8 + 14.0 * k, box.top() + 16}, QString(QChar(char16_t(u'x' + k))),
                  plot::TextStyle{.size = 10.5, .bold = true, .color = kAxisColors[k], .align = Qt::AlignLeft | Qt::AlignTop});
  canvas.beginClip(box);
  for (int k = first_series; k < first_series + series; ++k) {
    const QColor color = series > 1 ? kAxisColors[k] : kTrackAngleColor;
    std::vector<QPointF> run;
    // Unseen frames break the curve: nothing is drawn where the track says nothing.
    auto flush = [&] {
      if (run.size() > 1) canvas.polyline(run, plot::Stroke{color, 1.3});
      run.clear();
    };
    for (size_t f = 0; f < series_.size(); ++f) {
      const double v = series_[f][size_t(k)];
      if (std::isnan(v)) {
        flush();
        continue;
      }
      run.emplace_back(a.toX(double(f)), sy(v));
    }
    flush();
  }
  canvas.endClip();
  canvas.strokeRect(box, plot::Stroke{QColor(0xaa, 0xaa, 0xaa), 1});
}

void PartTracksView::paintMarks(QPainter& p) const {
  const FrameAxis a = axis();
  const double top = segmentBand().bottom(), bottom = showsAngle() ? anglePlot().bottom() : positionPlot().bottom();
  const int object = demonstrationObject();
  const Demonstration& d = doc_->demonstration();
  for (int i = 0; i < int(d.events.size()); ++i) {
    const ContactEvent& e = d.events[size_t(i)];
    if (e.object != object || object < 0) continue;
    const double x = a.toX(e.frame);
    const bool selected = i == doc_->selectedEvent();
    p.setPen(QPen(eventColor(e.type), selected ? 2.4 : 1.5));
    p.drawLine(QPointF(x, top), QPointF(x, bottom));
    // The timeline's marker shapes: grasp pointing up, release down.
    const double s = 5, y = top + 1;
    QPainterPath tri;
    if (e.type == EventType::Grasp) {
      tri.moveTo(x, y);
      tri.lineTo(x + s, y + 1.6 * s);
      tri.lineTo(x - s, y + 1.6 * s);
    } else {
      tri.moveTo(x, y + 1.6 * s);
      tri.lineTo(x + s, y);
      tri.lineTo(x - s, y);
    }
    tri.closeSubpath();
    p.setPen(Qt::NoPen);
    p.setBrush(eventColor(e.type));
    p.drawPath(tri);
  }
  // Where the operator placed this part again: the timeline's diamond over a dashed line.
  for (const PartCorrection& c : doc_->corrections()) {
    if (c.id != tracks_->tracks.object_ids[size_t(row_)]) continue;
    const double cx = a.toX(c.frame);
    p.setPen(QPen(objectColor(object), 1.2, Qt::DashLine));
    p.drawLine(QPointF(cx, top), QPointF(cx, bottom));
    paintPlacementMark(p, QRectF(cx - 5, top + 1, 10, 10), object, palette().color(QPalette::Text));
  }
  const double x = a.toX(doc_->currentFrame());
  p.setPen(QPen(kBusyColor, 1.5));
  p.drawLine(QPointF(x, 0), QPointF(x, height()));
}

void PartTracksView::paintEvent(QPaintEvent*) {
  QPainter p(this);
  p.setRenderHint(QPainter::Antialiasing);
  const QPalette pal = palette();
  p.fillRect(rect(), pal.color(QPalette::Base));
  QString message;
  if (!doc_->hasProject()) message = tr("No project");
  else if (!tracks_) message = doc_->trackDetection()->error().isEmpty() ? tr("No pose tracks") : doc_->trackDetection()->error();
  else if (row_ < 0 || series_.empty()) message = tr("Choose a part");
  if (!message.isEmpty()) {
    p.setPen(pal.color(QPalette::PlaceholderText));
    p.drawText(rect(), Qt::AlignCenter | Qt::TextWordWrap, message);
    return;
  }
  paintSegments(p);
  paintConfidence(p);
  paintStrip(p, positionPlot(), 0, 3, pos_lo_, pos_hi_, tr("position mm"));
  if (showsAngle()) paintStrip(p, anglePlot(), 3, 1, ang_lo_, ang_hi_, tr("angle °"));
  paintMarks(p);
}

void PartTracksView::mousePressEvent(QMouseEvent* e) {
  if (!doc_->hasProject() || e->button() != Qt::LeftButton || e->position().x() < FrameAxis::kGutter) return;
  scrubbing_ = true;
  doc_->setCurrentFrame(axis().toFrame(e->position().x()));
}

void PartTracksView::mouseMoveEvent(QMouseEvent* e) {
  if (scrubbing_) doc_->setCurrentFrame(axis().toFrame(e->position().x()));
}

void PartTracksView::mouseReleaseEvent(QMouseEvent*) { scrubbing_ = false; }

QString PartTracksView::toolTipAt(double x) const {
  if (!tracks_ || series_.empty() || x < FrameAxis::kGutter) return {};
  const int frame = axis().toFrame(x);
  QString tip = QStringLiteral("<b>%1</b>").arg(frameText(frame, doc_->fps()));
  if (frame < int(series_.size())) {
    const auto& v = series_[size_t(frame)];
    if (std::isnan(v[0])) tip += tr("<br>not seen");
    else
      tip += tr("<br>x %1, y %2, z %3 mm · %4° from the first rest · confidence %5%")
                 .arg(v[0], 0, 'f', 1)
                 .arg(v[1], 0, 'f', 1)
                 .arg(v[2], 0, 'f', 1)
                 .arg(v[3], 0, 'f', 1)
                 .arg(int(std::lround(confidence_[size_t(frame)] * 100)));
  }
  if (const int i = segmentAt(frame); i >= 0) {
    const auto& s = tracks_->segmentation.objects[size_t(row_)].segments[size_t(i)];
    tip += tr("<br>%1, frames %2–%3").arg(segmentName(s)).arg(s.first).arg(s.last);
    if (s.kind == perception::SegmentKind::Carry)
      tip += tr(" (grasp: last frame of the rest before, release: first of the rest after)");
    if (s.kind == perception::SegmentKind::Ride && s.carrier >= 0 && s.carrier < int(tracks_->tracks.object_ids.size()))
      tip += tr(" on %1").arg(QString::fromStdString(tracks_->tracks.object_ids[size_t(s.carrier)]));
  }
  for (const PartCorrection& c : doc_->corrections())
    if (c.frame == frame && c.id == tracks_->tracks.object_ids[size_t(row_)])
      tip += tr("<br>placed again here (the part models' detection follows it from there)");
  for (const Doubt& d : doubts())
    if (frame >= d.first && frame <= d.last)
      tip += tr("<br><span style='color:%1'>doubt, frames %2–%3:</span> %4")
                 .arg(kDoubtColor.darker(130).name())
                 .arg(d.first)
                 .arg(d.last)
                 .arg(d.message.toHtmlEscaped());
  return tip;
}

bool PartTracksView::event(QEvent* e) {
  if (e->type() == QEvent::ToolTip) {
    auto* he = static_cast<QHelpEvent*>(e);
    const QString tip = toolTipAt(he->pos().x());
    if (tip.isEmpty()) QToolTip::hideText();
    else QToolTip::showText(he->globalPos(), tip, this);
    return true;
  }
  return QWidget::event(e);
}

}  // namespace demoplan::ui
