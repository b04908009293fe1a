#include "ui/document/event_detection.h"

#include <filesystem>

#include "core/demo/settle_demonstration.h"
#include "core/error.h"
#include "perception/markers/marker_scene.h"
#include "perception/tracking/tracker_init.h"
#include "ui/document/document.h"
#include "ui/document/track_detection.h"

namespace demoplan::ui {

EventDetection::EventDetection(Document* doc) : QObject(doc), doc_(doc), runner_(this) {
  connect(&runner_, &ExtractionRunner::finished, this, &EventDetection::onFinished);
  connect(doc_->media(), &Media::markersChanged, this, &EventDetection::chooseTracker);
}

void EventDetection::setModelTracker(bool model) {
  if (model == model_tracker_) return;
  model_tracker_ = model;
  emit trackerChanged(model);
}

void EventDetection::chooseTracker() {
  const std::string& file = doc_->media()->markersFile();
  if (file.empty()) return;
  try {
    const perception::MarkerScene scene = perception::load_marker_scene(file);
    bool markers = false;
    for (const auto& o : scene.objects) markers = markers || !o.markers.empty();
    setModelTracker(!markers);
  } catch (const std::exception&) {
    // An unreadable scene is reported where it is opened; the choice stays as it was.
  }
}

QString EventDetection::blocker() const {
  if (!doc_->hasProject()) return tr("Open a project first");
  if (runner_.isRunning()) return tr("Detection is running");
  const Media& m = *doc_->media();
  if (!m.video()) return tr("Open the video first (File > Open Video…)");
  if (!m.camera()) return tr("Open the camera calibration first (File > Open Camera Calibration…)");
  if (m.markersFile().empty())
    return tr("Open the marker scene first (File > Open Marker Scene…): which markers are on which part");
  return {};
}

bool EventDetection::start() {
  if (!blocker().isEmpty()) return false;
  ExtractionJob job;
  job.video = doc_->media()->videoFile();
  job.camera = doc_->media()->cameraFile();
  job.markers = doc_->media()->markersFile();
  for (const auto& o : doc_->scene().objects) job.object_ids.push_back(o.id);
  job.task = doc_->sceneReference().is_cell() ? doc_->scene().name : doc_->sceneReference().task;
  job.scene = doc_->sharedScene();
  if (model_tracker_) {
    job.model_tracker = true;
    job.data_dir = doc_->dataDir();
    try {
      job.init = modelTrackerStart(&job.init_source);
    } catch (const std::exception& e) {
      emit done(ExtractionOutcome{false, e.what(), {}, {}, 0, 0.0});
      return false;
    }
  }
  return runner_.start(std::move(job));
}

perception::TrackerInit EventDetection::modelTrackerStart(std::string* source) const {
  perception::TrackerInit init;
  std::string from;
  const std::string& markers = doc_->media()->markersFile();
  const auto init_file = std::filesystem::path(markers).parent_path() / "init.json";
  if (!markers.empty() && std::filesystem::is_regular_file(init_file)) {
    from = init_file.string();
    init = perception::load_tracker_init(from);
  } else if (doc_->hasProject()) {
    from = kPosesAtFrameZero;
    const PoseList poses = doc_->demoPosesAt(0);
    const auto& objects = doc_->scene().objects;
    for (size_t k = 0; k < objects.size() && k < poses.size(); ++k) init.parts.push_back({objects[k].id, poses[k]});
    // A part the marker scene tracks beyond the project's (a tray, not planned for) has no start
    // the operator could place here.
    if (!markers.empty())
      for (const auto& o : perception::load_marker_scene(markers).objects)
        if (!init.find(o.id))
          throw InputError(markers, "objects",
                           "part '" + o.id + "' is not in the project's scene, so it has no start to place: give every "
                           "part's pose in frame 0 in " + init_file.string());
  }
  // The parts the operator placed again in the GUI, after those of init.json (a placement of the
  // same part in the same frame replaces the file's).
  const std::string project = doc_->filePath().isEmpty() ? "the project" : doc_->filePath().toStdString();
  const auto& placed = doc_->corrections();
  for (size_t i = 0; i < placed.size(); ++i) {
    const PartCorrection& c = placed[i];
    const std::string field = "tracker_corrections[" + std::to_string(i) + "]";
    if (!init.find(c.id)) throw InputError(project, field + ".id", "part '" + c.id + "' has no start in " + from);
    if (c.frame <= init.frame)
      throw InputError(project, field + ".frame",
                       "part '" + c.id + "' is placed again in frame " + std::to_string(c.frame) +
                           ", not after the start frame " + std::to_string(init.frame) + " of " + from);
    std::erase_if(init.corrections, [&](const PartCorrection& f) { return f.id == c.id && f.frame == c.frame; });
    init.corrections.push_back(c);
  }
  if (!placed.empty()) from += " and the parts placed again in the project";
  if (source) *source = from;
  return init;
}

void EventDetection::onFinished(const ExtractionOutcome& o) {
  // What the tracker measured, frame by frame, for the Part Tracks panel: also when it found no
  // event, as the tracks then show why.
  if (o.ok) doc_->trackDetection()->showVideoTracks(o.tracks, QString::fromStdString(o.tracker));
  if (o.ok && o.demonstration.events.empty()) {
    ExtractionOutcome none = o;
    none.ok = false;
    none.error = "no grasp or release was found in the video (View > Part Tracks shows what the tracker measured)";
    emit done(none);
    return;
  }
  // Measured rest poses float a few millimetres above or sink into their supports: put onto
  // them, as the planner needs (the CLI's plan does the same with a measured --demo).
  if (o.ok)
    doc_->replaceDemonstration(settle_on_supports(doc_->scene(), o.demonstration),
                               tr("Detect events in the video (%1 events)").arg(o.demonstration.events.size()));
  emit done(o);
}

}  // namespace demoplan::ui
