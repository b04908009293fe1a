#include "ui/document/document.h"

#include <QFileInfo>
#include <QUndoCommand>
#include <algorithm>
#include <filesystem>

#include "core/error.h"
#include "core/demo/benchmark_demonstration.h"
#include "perception/camera/camera_model.h"
#include "perception/video/video_reader.h"
#include "ui/document/demo_poses.h"

namespace demoplan::ui {

namespace {

constexpr double kLowConfidence = 0.5;

// Every demonstration edit as a before/after pair: demonstrations are small (a few events of a
// few objects), and a snapshot cannot get an index wrong after an earlier undo.
class DemoCommand : public QUndoCommand {
public:
  DemoCommand(Document* doc, const QString& text, Demonstration before, Demonstration after, int sel_before,
              int sel_after, int merge_id, long merge_key)
      : QUndoCommand(text),
        doc_(doc),
        before_(std::move(before)),
        after_(std::move(after)),
        sel_before_(sel_before),
        sel_after_(sel_after),
        merge_id_(merge_id),
        merge_key_(merge_key) {}
  void redo() override { doc_->applyDemonstration(after_, sel_after_); }
  void undo() override { doc_->applyDemonstration(before_, sel_before_); }
  int id() const override { return merge_id_; }
  bool mergeWith(const QUndoCommand* other) override {
    auto* o = dynamic_cast<const DemoCommand*>(other);
    if (!o || o->merge_key_ != merge_key_) return false;
    after_ = o->after_;
    sel_after_ = o->sel_after_;
    return true;
  }

private:
  Document* doc_;
  Demonstration before_, after_;
  int sel_before_, sel_after_;
  int merge_id_;
  long merge_key_;
};

constexpr int kMergePose = 1;
constexpr int kMergeConfidence = 2;

QString q(const std::string& s) { return QString::fromStdString(s); }

const char* type_word(EventType t) { return t == EventType::Grasp ? "grasp" : "release"; }

}  // namespace

Document::Document(std::string default_data_dir, QObject* parent)
    : QObject(parent),
      data_dir_(std::move(default_data_dir)),
      mesh_cache_(std::make_unique<MeshCache>()),
      runner_(this),
      extractor_(this) {
  connect(&extractor_, &ExtractionRunner::finished, this, [this](const ExtractionOutcome& o) {
    if (o.ok) {
      if (o.demonstration.events.empty()) {
        ExtractionOutcome none = o;
        none.ok = false;
        none.error = "no grasp or release was found in the video";
        emit extractionDone(none);
        return;
      }
      replaceDemonstration(o.demonstration, tr("Detect events in the video (%1 events)").arg(o.demonstration.events.size()));
    }
    emit extractionDone(o);
    emit stepsChanged();
  });
  connect(&undo_, &QUndoStack::cleanChanged, this, [this] { emit modifiedChanged(isModified()); });
  connect(&runner_, &PlanRunner::finished, this, &Document::onPlanFinished);
  connect(&runner_, &PlanRunner::started, this, &Document::stepsChanged);
  connect(&runner_, &PlanRunner::cancelled, this, [this](const PlanSnapshot& last) {
    auto r = std::make_shared<PlanResultData>(result_ ? *result_ : PlanResultData{});
    if (!result_) {
      r->summary.message = "cancelled after " + std::to_string(last.iterations) + " iterations";
      r->summary.iterations = last.iterations;
      r->summary.trees = last.trees;
      r->summary.nodes = last.nodes;
      r->summary.planning_time_s = last.elapsed_s;
      r->summary.demonstration_digest = "";
      r->cancelled = true;
      r->state_nodes = last.state_nodes;
      result_ = r;
      emit resultChanged();
    }
    emit stepsChanged();
  });
}

Document::~Document() = default;

// ---------------------------------------------------------------------------------- files

void Document::loadScene(const SceneReference& ref, std::shared_ptr<const Scene>& scene,
                         std::shared_ptr<const BenchmarkTask>& task) const {
  const std::string dir = ref.data_dir.empty() ? data_dir_ : ref.data_dir;
  auto t = std::make_shared<BenchmarkTask>(load_benchmark_task(dir, ref.task));
  SceneLoadOptions options;
  options.load_visual_meshes = true;
  options.mesh_cache = mesh_cache_.get();
  scene = std::make_shared<const Scene>(build_benchmark_scene(*t, ref.robot, ref.pose, options));
  task = std::move(t);
}

std::vector<std::string> Document::newFromBenchmark(const std::string& task_name, const std::string& robot, int pose) {
  Project p;
  p.scene.task = task_name;
  p.scene.robot = robot;
  p.scene.pose = pose;
  std::shared_ptr<const Scene> scene;
  std::shared_ptr<const BenchmarkTask> task;
  loadScene(p.scene, scene, task);
  DeckPlacementReport deck;
  p.demonstration = demonstration_from_benchmark(*task, *scene, PoseSource::Subgoals, &deck);
  install(std::move(p), std::move(scene), std::move(task), QString());
  return deck.notes();
}

void Document::open(const QString& file) {
  const std::string path = QFileInfo(file).absoluteFilePath().toStdString();
  Project p = load_project(path);
  std::shared_ptr<const Scene> scene;
  std::shared_ptr<const BenchmarkTask> task;
  try {
    loadScene(p.scene, scene, task);
  } catch (const InputError& e) {
    throw InputError(path, "scene", std::string("cannot load the scene it refers to: ") + e.what());
  }
  std::vector<std::string> ids;
  for (const auto& o : scene->objects) ids.push_back(o.id);
  if (ids != p.demonstration.object_ids) {
    auto join = [](const std::vector<std::string>& v) {
      std::string s;
      for (const auto& x : v) s += (s.empty() ? "" : ", ") + x;
      return "[" + s + "]";
    };
    throw InputError(path, "demonstration.objects",
                     "lists " + join(p.demonstration.object_ids) + " but the scene " + p.scene.task + " has " +
                         join(ids) + " (in this order)");
  }
  install(std::move(p), std::move(scene), std::move(task), QString::fromStdString(path));
}

void Document::install(Project p, std::shared_ptr<const Scene> scene, std::shared_ptr<const BenchmarkTask> task,
                       const QString& file) {
  if (runner_.isRunning()) runner_.cancel();
  if (extractor_.isRunning()) extractor_.cancel();
  project_ = std::move(p);
  scene_ = std::move(scene);
  task_ = std::move(task);
  file_ = file;
  template_ = false;
  extra_modified_ = false;
  exported_to_.clear();
  undo_.clear();
  undo_.setClean();
  selected_event_ = -1;
  selected_object_ = -1;
  display_mode_ = DisplayMode::Demonstration;
  playback_t_ = 0.0;
  issues_ = validate(project_.demonstration);
  result_.reset();
  interpolator_.reset();
  // Video and camera: a missing or unreadable file is reported on the Video step, not fatal.
  video_.reset();
  video_error_.clear();
  if (!project_.video.empty()) {
    try {
      video_ = std::make_unique<perception::VideoReader>(project_.video);
    } catch (const std::exception& e) {
      video_error_ = QString::fromUtf8(e.what());
    }
  }
  camera_.reset();
  camera_error_.clear();
  if (!project_.camera.empty()) {
    try {
      camera_ = std::make_unique<perception::Camera>(perception::load_camera(project_.camera));
    } catch (const std::exception& e) {
      camera_error_ = QString::fromUtf8(e.what());
    }
  }
  frame_ = std::clamp(project_.frame, 0, std::max(0, frameCount() - 1));
  loadResultPath();
  emit projectLoaded();
  emit fileChanged();
  emit demonstrationChanged();
  emit selectionChanged();
  emit currentFrameChanged(frame_);
  emit displayChanged();
  emit videoChanged();
  emit cameraChanged();
  emit plannerSettingsChanged();
  emit resultChanged();
  emit modifiedChanged(false);
  emit stepsChanged();
}

void Document::loadResultPath() {
  if (!project_.result) return;
  auto r = std::make_shared<PlanResultData>();
  r->summary = *project_.result;
  if (!r->summary.path.empty()) {
    try {
      Path path = load_path(r->summary.path);
      if (path.object_ids != project_.demonstration.object_ids || path.robot != project_.scene.robot ||
          path.robot_pose != project_.scene.pose)
        throw InputError(r->summary.path, "", "was planned for another scene");
      r->path = std::move(path);
    } catch (const std::exception& e) {
      r->summary.message = std::string("the path file cannot be read: ") + e.what();
      r->summary.valid = false;
    }
  }
  result_ = r;
  if (result_->path) interpolator_ = std::make_unique<PathInterpolator>(*scene_, *result_->path);
}

Project Document::project() const {
  Project p = project_;
  p.frame = frame_;
  if (result_ && !result_->cancelled) p.result = result_->summary;
  else p.result.reset();
  return p;
}

void Document::writeFiles(const QString& file, Project& p) const {
  const std::string path = QFileInfo(file).absoluteFilePath().toStdString();
  if (result_ && result_->path && p.result) {
    std::filesystem::path result_file(path);
    result_file.replace_extension(".path.json");
    save_path(result_file.string(), *result_->path);
    p.result->path = result_file.string();
  }
  save_project(path, p);
}

void Document::save() {
  if (file_.isEmpty() || template_) throw std::logic_error("save: the project has no file of its own yet");
  saveAs(file_);
}

void Document::saveAs(const QString& file) {
  Project p = project();
  writeFiles(file, p);
  if (result_ && p.result) {
    auto r = std::make_shared<PlanResultData>(*result_);
    r->summary.path = p.result->path;
    result_ = r;
  }
  file_ = QFileInfo(file).absoluteFilePath();
  template_ = false;
  extra_modified_ = false;
  undo_.setClean();
  emit fileChanged();
  emit modifiedChanged(false);
  emit saved(file_);
}

void Document::saveCopy(const QString& file) const {
  Project p = project();
  writeFiles(file, p);
}

QString Document::displayName() const {
  if (!hasProject()) return tr("No project");
  if (file_.isEmpty()) return tr("Untitled (%1)").arg(q(project_.scene.task));
  return QFileInfo(file_).fileName();
}

void Document::setTemplate(bool t) {
  template_ = t;
  emit fileChanged();
}

void Document::setFilePath(const QString& file) {
  file_ = file.isEmpty() ? QString() : QFileInfo(file).absoluteFilePath();
  template_ = false;
  emit fileChanged();
}

bool Document::isModified() const { return hasProject() && (extra_modified_ || !undo_.isClean()); }

void Document::setModified() {
  const bool was = isModified();
  extra_modified_ = true;
  if (!was) emit modifiedChanged(true);
}

// ------------------------------------------------------------------------------ edits

void Document::applyDemonstration(const Demonstration& demo, int selected_event) {
  project_.demonstration = demo;
  issues_ = validate(project_.demonstration);
  const int n = static_cast<int>(demo.events.size());
  selected_event_ = selected_event < n ? selected_event : -1;
  if (selected_event_ >= 0) selected_object_ = demo.events[selected_event_].object;
  emit demonstrationChanged();
  emit selectionChanged();
  emit displayChanged();
  emit stepsChanged();
}

void Document::pushEdit(const QString& text, const Demonstration& after, int selected_after, int merge_id) {
  long key = -1;
  if (merge_id >= 0) key = static_cast<long>(selected_after) * 4096 + selected_object_;
  undo_.push(new DemoCommand(this, text, project_.demonstration, after, selected_event_, selected_after, merge_id, key));
}

int Document::addEvent(int frame, int object, EventType type) {
  if (!hasProject() || object < 0 || object >= static_cast<int>(project_.demonstration.object_ids.size())) return -1;
  Demonstration d = project_.demonstration;
  const int index = static_cast<int>(insert_event(d, new_event_at(d, frame, object, type)));
  pushEdit(tr("Add %1 of %2 at frame %3").arg(type_word(type), q(d.object_ids[object])).arg(frame), d, index);
  return index;
}

void Document::removeEvent(int index) {
  if (index < 0 || index >= static_cast<int>(project_.demonstration.events.size())) return;
  Demonstration d = project_.demonstration;
  const ContactEvent& e = d.events[index];
  const QString text =
      tr("Delete %1 of %2 at frame %3").arg(type_word(e.type), q(d.object_ids[e.object])).arg(e.frame);
  remove_event(d, static_cast<size_t>(index));
  pushEdit(text, d, -1);
}

void Document::moveEvent(int index, int frame) {
  if (index < 0 || index >= static_cast<int>(project_.demonstration.events.size())) return;
  frame = std::max(0, frame);
  if (project_.demonstration.events[index].frame == frame) return;
  Demonstration d = project_.demonstration;
  const ContactEvent& e = d.events[index];
  const QString text = tr("Move %1 of %2 from frame %3 to %4")
                           .arg(type_word(e.type), q(d.object_ids[e.object]))
                           .arg(e.frame)
                           .arg(frame);
  const int to = static_cast<int>(move_event(d, static_cast<size_t>(index), frame));
  pushEdit(text, d, to);
}

void Document::setObjectPose(int event, int object, const Pose& world_pose, int merge_key) {
  const Demonstration& cur = project_.demonstration;
  if (event < 0 || event >= static_cast<int>(cur.events.size()) || object < 0 ||
      object >= static_cast<int>(cur.object_ids.size()))
    return;
  Demonstration d = cur;
  // The stored pose may be relative to a robot link (objects riding on the KMR's deck).
  Pose stored = world_pose;
  const std::string& frame = d.events[event].pose_frame(object);
  if (!frame.empty()) {
    const int link = scene_->robot.model.link_index(frame);
    if (link >= 0)
      stored = link_pose(scene_->robot.model, initialConfiguration(), scene_->robot.base, link).inverse() * world_pose;
  }
  const std::vector<size_t> events = rest_events(d, static_cast<size_t>(event), object);
  for (size_t i : events) set_object_pose(d, i, object, stored);
  QString text = tr("Move %1").arg(q(d.object_ids[object]));
  if (events.size() > 1)
    text += tr(" (rest from frame %1 to %2)").arg(d.events[events.front()].frame).arg(d.events[events.back()].frame);
  else
    text += tr(" at frame %1").arg(d.events[event].frame);
  const long key = (static_cast<long>(event) * 4096 + object) * 1024 + merge_key;
  undo_.push(new DemoCommand(this, text, cur, d, selected_event_, selected_event_, merge_key >= 0 ? kMergePose : -1, key));
}

void Document::setEventConfidence(int event, double confidence) {
  if (event < 0 || event >= static_cast<int>(project_.demonstration.events.size())) return;
  Demonstration d = project_.demonstration;
  d.events[event].confidence = std::clamp(confidence, 0.0, 1.0);
  undo_.push(new DemoCommand(this, tr("Set confidence"), project_.demonstration, d, selected_event_, selected_event_,
                             kMergeConfidence, event));
}

void Document::replaceDemonstration(const Demonstration& demo, const QString& text) {
  pushEdit(text, demo, -1);
}

// ------------------------------------------------------------------ selection and time

void Document::selectEvent(int index) {
  const int n = static_cast<int>(project_.demonstration.events.size());
  if (index >= n) index = -1;
  const bool changed = index != selected_event_;
  selected_event_ = index;
  if (index >= 0) selected_object_ = project_.demonstration.events[index].object;
  if (changed || index >= 0) emit selectionChanged();
  if (index >= 0) setCurrentFrame(project_.demonstration.events[index].frame);
}

void Document::selectObject(int object) {
  if (object >= static_cast<int>(project_.demonstration.object_ids.size())) object = -1;
  if (object == selected_object_) return;
  selected_object_ = object;
  emit selectionChanged();
  emit displayChanged();
}

int Document::editEvent() const {
  const auto& events = project_.demonstration.events;
  if (selected_event_ >= 0 && selected_event_ < static_cast<int>(events.size())) return selected_event_;
  if (events.empty()) return -1;
  int last = 0;
  for (size_t i = 0; i < events.size(); ++i)
    if (events[i].frame <= frame_) last = static_cast<int>(i);
  return last;
}

void Document::setCurrentFrame(int frame) {
  frame = std::clamp(frame, 0, std::max(0, frameCount() - 1));
  const bool mode_changed = display_mode_ != DisplayMode::Demonstration;
  display_mode_ = DisplayMode::Demonstration;
  if (frame == frame_ && !mode_changed) return;
  frame_ = frame;
  emit currentFrameChanged(frame_);
  emit displayChanged();
}

int Document::frameCount() const {
  if (video_) return std::max(1, video_->frame_count());
  int n = task_ ? task_->frames : 1;
  for (const auto& e : project_.demonstration.events) n = std::max(n, e.frame + 1);
  return std::max(1, n);
}

double Document::fps() const {
  if (video_ && video_->fps() > 0) return video_->fps();
  return project_.demonstration.fps > 0 ? project_.demonstration.fps : 30.0;
}

void Document::setPlaybackT(double t) {
  t = std::clamp(t, 0.0, 1.0);
  if (display_mode_ == DisplayMode::Result && t == playback_t_) return;
  display_mode_ = DisplayMode::Result;
  playback_t_ = t;
  emit displayChanged();
}

void Document::showDemonstration() {
  if (display_mode_ == DisplayMode::Demonstration) return;
  display_mode_ = DisplayMode::Demonstration;
  emit displayChanged();
}

Eigen::VectorXd Document::initialConfiguration() const {
  if (!scene_) return {};
  Eigen::VectorXd q = scene_->robot.initial_configuration;
  if (q.size() != scene_->robot.model.nq) q = Eigen::VectorXd::Zero(scene_->robot.model.nq);
  return q;
}

PoseList Document::demoPosesAt(double frame) const {
  if (!scene_) return {};
  return demo_poses_at_frame(*scene_, project_.demonstration, frame, initialConfiguration());
}

SceneState Document::displayState() const {
  SceneState s;
  if (!scene_) return s;
  if (display_mode_ == DisplayMode::Result && interpolator_) return interpolator_->at(playback_t_);
  s.q = initialConfiguration();
  s.objects = demoPosesAt(frame_);
  return s;
}

// ----------------------------------------------------------------------- video, camera

void Document::setVideo(const QString& file) {
  project_.video = file.isEmpty() ? std::string() : QFileInfo(file).absoluteFilePath().toStdString();
  video_.reset();
  video_error_.clear();
  if (!project_.video.empty()) {
    try {
      video_ = std::make_unique<perception::VideoReader>(project_.video);
    } catch (const std::exception& e) {
      video_error_ = QString::fromUtf8(e.what());
    }
  }
  setModified();
  frame_ = std::clamp(frame_, 0, std::max(0, frameCount() - 1));
  emit videoChanged();
  emit currentFrameChanged(frame_);
  emit displayChanged();
  emit stepsChanged();
}

void Document::setCamera(const QString& file) {
  project_.camera = file.isEmpty() ? std::string() : QFileInfo(file).absoluteFilePath().toStdString();
  camera_.reset();
  camera_error_.clear();
  if (!project_.camera.empty()) {
    try {
      camera_ = std::make_unique<perception::Camera>(perception::load_camera(project_.camera));
    } catch (const std::exception& e) {
      camera_error_ = QString::fromUtf8(e.what());
    }
  }
  setModified();
  emit cameraChanged();
  emit stepsChanged();
}

void Document::setMarkers(const QString& file) {
  project_.markers = file.isEmpty() ? std::string() : QFileInfo(file).absoluteFilePath().toStdString();
  setModified();
  emit stepsChanged();
}

QString Document::extractionBlocker() const {
  if (!hasProject()) return tr("Open a project first");
  if (extractor_.isRunning()) return tr("Detection is running");
  if (!video_) return tr("Open the video first (File > Open Video…)");
  if (!camera_) return tr("Open the camera calibration first (File > Open Camera Calibration…)");
  if (project_.markers.empty()) return tr("Open the marker scene first (File > Open Marker Scene…): which markers are on which part");
  return {};
}

bool Document::startExtraction() {
  if (!extractionBlocker().isEmpty()) return false;
  ExtractionJob job;
  job.video = project_.video;
  job.camera = project_.camera;
  job.markers = project_.markers;
  for (const auto& o : scene_->objects) job.object_ids.push_back(o.id);
  job.task = project_.scene.task;
  return extractor_.start(std::move(job));
}

// ----------------------------------------------------------------------------- planning

void Document::setPlannerSettings(const PlannerSettings& s) {
  project_.planner = s;
  setModified();
  emit plannerSettingsChanged();
}

bool Document::startPlanning() {
  if (!hasProject() || runner_.isRunning() || !issues_.empty()) return false;
  PlanJob job;
  job.scene = scene_;
  job.demonstration = project_.demonstration;
  job.params = project_.planner.solve_params();
  job.task = project_.scene.task;
  job.robot = project_.scene.robot;
  job.robot_pose = project_.scene.pose;
  return runner_.start(std::move(job));
}

void Document::onPlanFinished(const PlanOutcome& o) {
  auto r = std::make_shared<PlanResultData>();
  ResultSummary& s = r->summary;
  s.demonstration_digest = demonstration_digest(project_.demonstration);
  if (!o.error.empty()) {
    s.message = o.error;
  } else {
    const PlanResult& p = o.result.plan;
    s.solved = p.solved;
    s.planning_time_s = p.planning_time_s;
    s.iterations = p.iterations;
    s.trees = p.trees;
    s.nodes = p.nodes;
    r->unsampled_transitions = p.unsampled_transitions;
    r->infeasible_picks = o.infeasible_picks;
    r->state_nodes = p.state_nodes;
    r->cancelled = p.cancelled;
    if (o.graph)
      for (const auto& st : o.graph->states) r->state_names.push_back(st.name);
    if (p.solved) {
      const ValidationReport& v = o.result.validation;
      s.valid = v.valid;
      s.message = v.message;
      s.validated_against = o.validation_task.source;
      s.length_robot_rad = v.length.robot;
      s.length_object_m = v.length.object_translation;
      s.length_object_rad = v.length.object_rotation;
      s.grasps = v.grasps;
      s.shortened = o.result.shortened;
      if (!o.result.shortcut_rejection.empty())
        r->shortcut_note = "shortened path dropped: " + o.result.shortcut_rejection;
      r->path = p.path;
    } else {
      s.message = p.message;
    }
  }
  result_ = r;
  interpolator_.reset();
  if (result_->path) interpolator_ = std::make_unique<PathInterpolator>(*scene_, *result_->path);
  playback_t_ = 0.0;
  setModified();
  emit resultChanged();
  emit stepsChanged();
  emit displayChanged();
}

bool Document::resultStale() const {
  return result_ && !result_->cancelled &&
         result_->summary.demonstration_digest != demonstration_digest(project_.demonstration);
}

void Document::clearResult() {
  result_.reset();
  interpolator_.reset();
  display_mode_ = DisplayMode::Demonstration;
  setModified();
  emit resultChanged();
  emit stepsChanged();
  emit displayChanged();
}

void Document::markExported(const QString& file) {
  exported_to_ = file;
  emit stepsChanged();
}

// -------------------------------------------------------------------------------- steps

StepState Document::stepState(Step step) const {
  if (!hasProject()) return {StepStatus::None, tr("Open a project (File > Open) or the sample")};
  const Demonstration& d = project_.demonstration;
  switch (step) {
    case Step::Video: {
      if (!video_error_.isEmpty())
        return {StepStatus::Error, video_error_ + tr(" — File > Open Video… to locate the recording")};
      if (!video_)
        return {StepStatus::Warning,
                tr("No video: the events come from the benchmark's labels. File > Open Video… adds the recording")};
      QString msg = tr("%1: %2 frames at %3 fps")
                        .arg(QFileInfo(videoPath()).fileName())
                        .arg(video_->frame_count())
                        .arg(video_->fps(), 0, 'g', 3);
      if (!camera_error_.isEmpty()) return {StepStatus::Warning, msg + tr("; camera: ") + camera_error_};
      if (!camera_) return {StepStatus::Warning, msg + tr("; no camera calibration: outlines cannot be drawn")};
      if (!camera_->world_T_camera)
        return {StepStatus::Warning, msg + tr("; the camera has no pose in the world: outlines cannot be drawn")};
      return {StepStatus::Ok, msg + tr("; camera calibrated")};
    }
    case Step::Events: {
      if (!issues_.empty()) {
        QString msg = q(issues_.front().message);
        if (issues_.size() > 1) msg += tr(" (and %1 more)").arg(issues_.size() - 1);
        return {StepStatus::Error, msg};
      }
      int low = 0;
      for (const auto& e : d.events) low += e.confidence < kLowConfidence;
      if (low > 0) return {StepStatus::Warning, tr("%1 event(s) below %2% confidence: check them").arg(low).arg(kLowConfidence * 100)};
      return {StepStatus::Ok, tr("%1 events on %2 parts, all rules hold").arg(d.events.size()).arg(d.object_ids.size())};
    }
    case Step::Poses: {
      if (!issues_.empty()) return {StepStatus::None, tr("Fix the events first")};
      try {
        const ConstraintGraph g = build_constraint_graph(*scene_, d);
        return {StepStatus::Ok, tr("%1 placements and %2 grasp states")
                                    .arg(g.states_of_kind(StateKind::Placement).size())
                                    .arg(g.states_of_kind(StateKind::Grasp).size())};
      } catch (const std::exception& e) {
        return {StepStatus::Error, QString::fromUtf8(e.what())};
      }
    }
    case Step::Plan: {
      if (runner_.isRunning()) return {StepStatus::Busy, tr("Planning…")};
      if (!result_) return {StepStatus::None, tr("Not planned yet: press Plan (F5)")};
      const ResultSummary& s = result_->summary;
      if (result_->cancelled) return {StepStatus::Warning, tr("Cancelled: ") + q(s.message)};
      if (resultStale()) return {StepStatus::Warning, tr("The demonstration changed since the last plan: plan again")};
      if (!s.solved && !result_->infeasible_picks.empty()) {
        const std::string first = result_->infeasible_picks.substr(0, result_->infeasible_picks.find(':'));
        return {StepStatus::Error, tr("No path: %1 from this robot base pose (see the Planner panel)").arg(q(first))};
      }
      if (!s.solved) return {StepStatus::Error, tr("No path: ") + q(s.message)};
      if (!s.valid) return {StepStatus::Warning, tr("The validator rejects the path: ") + q(s.message)};
      return {StepStatus::Ok, tr("Valid path found in %1 s").arg(s.planning_time_s, 0, 'f', 2)};
    }
    case Step::Export: {
      if (!exported_to_.isEmpty()) return {StepStatus::Ok, tr("Exported to %1").arg(exported_to_)};
      if (result_ && result_->path && result_->summary.valid && !resultStale())
        return {StepStatus::None, tr("Ready to export: File > Export Program… (Ctrl+E)")};
      return {StepStatus::None, tr("Plan a valid path first")};
    }
  }
  return {};
}

}  // namespace demoplan::ui
