#pragma once
// Finds the grasp and release events and the parts' poses in the video (perception's
// extract_demonstration) on a background thread, with progress and cancel. The result is a
// demonstration in the scene's object order, ready to replace the current one as one undoable
// edit.
#include <memory>
#include <string>
#include <vector>

#include "core/demo/demonstration.h"
#include "perception/tracking/tracker_init.h"
#include "ui/document/background_job.h"

namespace demoplan::perception {
struct TracksDemonstration;  // perception/events/tracks_demonstration.h: kept out of document.h
}

namespace demoplan::ui {

struct ExtractionJob {
  std::string video, camera, markers;  // files
  std::vector<std::string> object_ids;  // the scene's parts, in its order
  std::string task;
  std::shared_ptr<const Scene> scene;  // the project's: rests are put onto its supports
  // The model-based tracker (no markers): the parts' meshes from the task or cell the marker
  // scene names (in `data_dir`), started from `init` (`init_source` names it in messages).
  bool model_tracker = false;
  std::string data_dir;
  perception::TrackerInit init;
  std::string init_source;
};

struct ExtractionOutcome {
  bool ok = false;
  std::string error;
  Demonstration demonstration;
  std::vector<std::string> warnings;
  int frames = 0;
  double seconds = 0.0;
  // Every part's pose and confidence in every frame as the tracker measured it (the tray too),
  // cut into rests and carries: what the Part Tracks panel shows after a detection.
  std::shared_ptr<const perception::TracksDemonstration> tracks;
  std::string tracker;  // its name ("markers", "model")
};

class ExtractionRunner : public BackgroundJob {
  Q_OBJECT
public:
  using BackgroundJob::BackgroundJob;
  bool start(ExtractionJob job);

signals:
  void progress(int done, int total);
  void finished(const ExtractionOutcome& outcome);
};

// Puts an extracted demonstration's objects in `ids`' order; throws InputError naming the part
// the extraction does not track.
Demonstration reorder_objects(const Demonstration& demo, const std::vector<std::string>& ids, const std::string& source);

}  // namespace demoplan::ui
