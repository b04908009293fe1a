#include "ui/widgets/part_tracks_panel.h"

#include <QComboBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QSignalBlocker>
#include <QVBoxLayout>
#include <cmath>

#include "perception/events/tracks_demonstration.h"
#include "perception/tracking/track_coverage.h"
#include "ui/widgets/part_tracks_view.h"
#include "ui/widgets/style.h"

namespace demoplan::ui {

PartTracksPanel::PartTracksPanel(Document* doc, QWidget* parent) : QWidget(parent), doc_(doc) {
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  layout->setSpacing(2);
  auto* bar = new QHBoxLayout;
  bar->setContentsMargins(8, 4, 8, 0);
  auto* label = new QLabel(tr("Part"), this);
  parts_ = new QComboBox(this);
  parts_->setSizeAdjustPolicy(QComboBox::AdjustToContents);
  parts_->setToolTip(tr("The part whose track is shown (follows the selection)"));
  label->setBuddy(parts_);
  summary_ = new QLabel(this);
  summary_->setTextFormat(Qt::RichText);
  // "lost from frame N on": the playhead to where the tracker lost the part.
  connect(summary_, &QLabel::linkActivated, this, [this](const QString& link) {
    if (link.startsWith(QLatin1String("lost:"))) doc_->setCurrentFrame(link.mid(5).toInt());
  });
  // A long line is cut, not a reason for the dock (and the window) to be wider.
  summary_->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Preferred);
  bar->addWidget(label);
  bar->addWidget(parts_);
  bar->addWidget(summary_, 1);
  layout->addLayout(bar);
  view_ = new PartTracksView(doc, this);
  layout->addWidget(view_, 1);

  connect(parts_, &QComboBox::currentIndexChanged, this, [this](int row) {
    view_->setRow(row);
    refreshSummary();
    // Choosing a planned part here selects it everywhere; a tray has no lane, so nothing is
    // selected (a click on the lane that was selected then brings its part back here).
    if (view_->tracks() && row >= 0)
      doc_->selectObject(doc_->demonstration().object_index(view_->tracks()->tracks.object_ids[size_t(row)]));
  });
  connect(view_, &PartTracksView::tracksReloaded, this, &PartTracksPanel::refill);
  connect(doc_, &Document::selectionChanged, this, &PartTracksPanel::followSelection);
  connect(doc_, &Document::demonstrationChanged, this, &PartTracksPanel::refreshSummary);
  refill();
}

void PartTracksPanel::refill() {
  const perception::TracksDemonstration* t = view_->tracks();
  {
    const QSignalBlocker block(parts_);
    parts_->clear();
    if (t)
      for (size_t r = 0; r < t->tracks.object_ids.size(); ++r) {
        const QString id = QString::fromStdString(t->tracks.object_ids[r]);
        const bool planned = r < t->tracks.planning.size() && t->tracks.planning[r];
        parts_->addItem(planned ? id : tr("%1 (not planned: a support)").arg(id));
      }
    parts_->setEnabled(parts_->count() > 0);
  }
  view_->setRow(parts_->count() > 0 ? 0 : -1);
  parts_->setCurrentIndex(view_->row());
  followSelection();
  refreshSummary();
}

void PartTracksPanel::followSelection() {
  const perception::TracksDemonstration* t = view_->tracks();
  const int object = doc_->selectedObject();
  if (!t || object < 0 || object >= int(doc_->demonstration().object_ids.size())) return;
  const int row = t->tracks.object_index(doc_->demonstration().object_ids[size_t(object)]);
  if (row < 0 || row == parts_->currentIndex()) return;
  const QSignalBlocker block(parts_);
  parts_->setCurrentIndex(row);
  view_->setRow(row);
  refreshSummary();
}

void PartTracksPanel::refreshSummary() {
  const perception::TracksDemonstration* t = view_->tracks();
  const int row = view_->row();
  if (!t || row < 0 || row >= int(t->segmentation.objects.size())) {
    summary_->clear();
    summary_->setToolTip(QString());
    return;
  }
  const perception::ObjectSegmentation& o = t->segmentation.objects[size_t(row)];
  int rests = 0, carries = 0, rides = 0;
  for (const auto& s : o.segments) {
    rests += s.kind == perception::SegmentKind::Rest;
    carries += s.kind == perception::SegmentKind::Carry;
    rides += s.kind == perception::SegmentKind::Ride;
  }
  auto count = [](int n, const QString& one, const QString& many) { return QString::number(n) + " " + (n == 1 ? one : many); };
  QString text = doc_->trackDetection()->source();
  if (!text.isEmpty()) text[0] = text[0].toUpper();
  text += (text.isEmpty() ? QString() : QStringLiteral(": ")) + count(rests, tr("rest"), tr("rests")) + ", " +
          count(carries, tr("carry"), tr("carries"));
  if (rides > 0) text += ", " + count(rides, tr("ride"), tr("rides"));
  // Lost for good by the model tracker (first, where the narrow dock does not cut it off): from
  // which frame, and how the operator brings it back.
  QString tip;
  if (doc_->trackDetection()->tracker() == QLatin1String("model") && size_t(row) < t->tracks.samples.size())
    if (const int lost = perception::track_coverage(t->tracks.samples[size_t(row)]).lost_for_good_from(); lost > 0) {
      text += tr(" · <a href='lost:%2' style='color:%1'>lost from frame %2 on</a>").arg(kErrorColor.name()).arg(lost);
      tip = tr("<br>Click it to go there. Where a later frame shows the part, Edit > Place Part Again Here "
               "(Ctrl+Shift+P) at that frame, move it onto the part in the video, and detect again (or give it in "
               "the \"corrections\" of init.json beside the marker scene, docs/perception.md).");
    }
  // The noise decides how wide a rest is: worth seeing next to the curves.
  text += tr(" · noise σ %1–%2 mm, %3° · %4 usable frames")
              .arg(o.noise.sigma_min * 1000, 0, 'f', 1)
              .arg(o.noise.sigma_max * 1000, 0, 'f', 1)
              .arg(o.noise.sigma_rotation * 180 / M_PI, 0, 'f', 1)
              .arg(o.noise.usable_frames);
  text += tr(" · <span style='color:%1'>▮</span> rest <span style='color:%2'>▮</span> carry "
             "<span style='color:%3'>▨</span> doubt · confidence <span style='color:%4'>▬</span> "
             "<span style='color:%5'>▬</span> <span style='color:%6'>▬</span> not seen <span style='color:%7'>▬</span>")
              .arg(kTrackRestColor.name(), objectColor(doc_->demonstration().object_index(t->tracks.object_ids[size_t(row)])).name(),
                   kDoubtColor.name(), kOkColor.name(), kWarningColor.name(), kErrorColor.name(), kUnseenColor.name());
  summary_->setText(text);
  summary_->setToolTip(text + tip);  // the line is cut where the dock is narrow
}

}  // namespace demoplan::ui
