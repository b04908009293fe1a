#pragma once
// The Events step from the benchmark task's pose tracks alone (issue 14: real demonstrations
// without labels): perception::demonstration_from_tracks cuts each part's track into rests and
// carries and builds the demonstration from them. It takes well under 0.2 s for a benchmark task,
// so it runs on the GUI thread. The result replaces the demonstration as one undoable edit; the
// tracks and their segmentation stay here for the Part Tracks panel, which shows why each event
// is where it is. A detection in the video (EventDetection) leaves the tracks it measured here
// too, with each frame's confidence, for any project, a cell's as well.
#include <QObject>
#include <QString>
#include <memory>

namespace demoplan::perception {
struct TracksDemonstration;  // perception/events/tracks_demonstration.h: kept out of document.h
}

namespace demoplan::ui {

class Document;

class TrackDetection : public QObject {
  Q_OBJECT
public:
  explicit TrackDetection(Document* doc);

  // What is missing to detect events from the tracks; empty when detect() can run.
  QString blocker() const;
  // Replaces the demonstration (one undo step) and returns the number of events. Throws (an
  // InputError naming the task file) when nothing can be detected; the project is then unchanged.
  int detect();

  // The tracks and their segmentation: those of the last detection (from the task's tracks or in
  // the video), else segmented from the task on first use. Null without a project or when there
  // are none (error() says why).
  std::shared_ptr<const perception::TracksDemonstration> tracks();
  QString error() const { return error_; }
  // Where the tracks come from, for the panel: the video's tracker (markers, model) or the task.
  QString source() const { return source_; }
  bool fromVideo() const { return !tracker_.isEmpty(); }
  // The video's tracker ("markers", "model"); empty for the task's tracks.
  QString tracker() const { return tracker_; }
  // The tracks a detection in the video measured (`tracker` names the tracker).
  void showVideoTracks(std::shared_ptr<const perception::TracksDemonstration> tracks, const QString& tracker);

signals:
  void tracksChanged();

private:
  void setTracks(std::shared_ptr<const perception::TracksDemonstration> tracks);

  Document* doc_;
  std::shared_ptr<const perception::TracksDemonstration> tracks_;
  QString error_;
  QString source_;
  QString tracker_;  // empty: the task's tracks, or none
};

}  // namespace demoplan::ui
