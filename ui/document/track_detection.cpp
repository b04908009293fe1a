#include "ui/document/track_detection.h"

#include "perception/events/tracks_demonstration.h"
#include "ui/document/document.h"

namespace demoplan::ui {

TrackDetection::TrackDetection(Document* doc) : QObject(doc), doc_(doc) {
  // Another project has other tracks: segment them again when asked.
  connect(doc_, &Document::projectLoaded, this, [this] { setTracks(nullptr); });
}

QString TrackDetection::blocker() const {
  if (!doc_->hasProject()) return tr("Open a project first");
  const BenchmarkTask* task = doc_->task();
  if (!task) return tr("Pose tracks come with benchmark tasks; this project's scene is a cell");
  if (task->frames <= 0 || task->raw_poses.empty())
    return tr("The benchmark task %1 has no pose tracks (objects_poses)").arg(QString::fromStdString(task->file));
  return {};
}

int TrackDetection::detect() {
  const QString why = blocker();
  if (!why.isEmpty()) throw std::runtime_error(why.toStdString());
  auto result = std::make_shared<perception::TracksDemonstration>(
      perception::demonstration_from_tracks(*doc_->task(), doc_->scene()));
  const int events = static_cast<int>(result->demonstration.events.size());
  const int doubts = static_cast<int>(result->demonstration.doubts.size());
  QString text = tr("Detect events from tracks (%1 events").arg(events);
  if (doubts > 0) text += tr(", %1 doubts").arg(doubts);
  doc_->replaceDemonstration(result->demonstration, text + QLatin1Char(')'));
  setTracks(std::move(result));
  return events;
}

void TrackDetection::showVideoTracks(std::shared_ptr<const perception::TracksDemonstration> tracks, const QString& tracker) {
  tracks_ = std::move(tracks);
  error_.clear();
  tracker_ = tracks_ ? tracker : QString();
  source_ = fromVideo() ? tr("from the video (%1 tracker)").arg(tracker == QLatin1String("markers") ? tr("marker") : tracker)
                       : QString();
  emit tracksChanged();
}

std::shared_ptr<const perception::TracksDemonstration> TrackDetection::tracks() {
  if (tracks_ || !error_.isEmpty() || !doc_->hasProject()) return tracks_;
  error_ = blocker();
  if (!error_.isEmpty()) return nullptr;
  // The panel only needs the segmentation; the demonstration stays the document's.
  try {
    auto t = std::make_shared<perception::TracksDemonstration>();
    t->tracks = perception::tracks_from_benchmark(*doc_->task());
    t->segmentation = perception::segment_tracks(t->tracks);
    tracks_ = std::move(t);
    source_ = tr("from the task's pose tracks");
  } catch (const std::exception& e) {
    error_ = QString::fromUtf8(e.what());
  }
  return tracks_;
}

void TrackDetection::setTracks(std::shared_ptr<const perception::TracksDemonstration> tracks) {
  tracks_ = std::move(tracks);
  error_.clear();
  tracker_.clear();
  source_ = tracks_ ? tr("from the task's pose tracks") : QString();
  emit tracksChanged();
}

}  // namespace demoplan::ui
