#include "ui/document/document.h"

#include <QFileInfo>
#include <QUndoCommand>
#include <algorithm>
#include <filesystem>
#include <utility>

#include "core/cell/cell_edits.h"
#include "core/cell/cell_scene.h"
#include "core/demo/settle_demonstration.h"
#include "core/demo/supported_rests.h"
#include "core/error.h"
#include "core/project/new_project.h"
#include "core/placement/base_clearance.h"
#include "core/project/placement_problem.h"
#include "core/project/project_scene.h"
#include "perception/camera/camera_model.h"
#include "perception/events/tracks_demonstration.h"
#include "perception/importers/bop_csv.h"
#include "perception/tracking/tracker_init_bop.h"
#include "perception/video/video_reader.h"
#include "ui/document/demo_poses.h"

namespace demoplan::ui {

namespace {


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

// A cell edit: the cell, the scene built from it and the demonstration that follows its parts,
// before and after; undo and redo swap them without rebuilding anything.
class CellCommand : public QUndoCommand {
public:
  struct State {
    Cell cell;
    std::shared_ptr<const Scene> scene;
    Demonstration demo;
  };
  CellCommand(Document* doc, const QString& text, State before, State after, int merge_key)
      : QUndoCommand(text), doc_(doc), before_(std::move(before)), after_(std::move(after)), merge_key_(merge_key) {}
  // The first redo is the edit itself: editCell has written the file already.
  void redo() override { doc_->applyCell(after_.cell, after_.scene, after_.demo, !std::exchange(first_, false)); }
  void undo() override { doc_->applyCell(before_.cell, before_.scene, before_.demo, true); }
  int id() const override { return merge_key_ >= 0 ? kMergeCell : -1; }
  bool mergeWith(const QUndoCommand* other) override {
    auto* o = dynamic_cast<const CellCommand*>(other);
    if (!o || o->merge_key_ != merge_key_) return false;
    after_ = o->after_;
    return true;
  }
  static constexpr int kMergeCell = 3;

private:
  Document* doc_;
  State before_, after_;
  int merge_key_;
  bool first_ = true;
};

// Another video, camera calibration or marker scene: the file before and after.
class MediaCommand : public QUndoCommand {
public:
  MediaCommand(Media* media, Media::File which, std::string before, std::string after, const QString& text)
      : QUndoCommand(text), media_(media), which_(which), before_(std::move(before)), after_(std::move(after)) {}
  void redo() override { media_->use(which_, after_); }
  void undo() override { media_->use(which_, before_); }

private:
  Media* media_;
  Media::File which_;
  std::string before_, after_;
};

// A task's robot stood elsewhere: the scene reference and the scene built for it, before and after.
class BaseCommand : public QUndoCommand {
public:
  struct State {
    SceneReference ref;
    std::shared_ptr<const Scene> scene;
  };
  BaseCommand(Document* doc, const QString& text, State before, State after)
      : QUndoCommand(text), doc_(doc), before_(std::move(before)), after_(std::move(after)) {}
  void redo() override { doc_->applySceneReference(after_.ref, after_.scene); }
  void undo() override { doc_->applySceneReference(before_.ref, before_.scene); }

private:
  Document* doc_;
  State before_, after_;
};

// Parts placed again for the part-model tracker: the list before and after (a few entries).
class CorrectionsCommand : public QUndoCommand {
public:
  CorrectionsCommand(Document* doc, const QString& text, std::vector<PartCorrection> before,
                     std::vector<PartCorrection> after, long merge_key)
      : QUndoCommand(text), doc_(doc), before_(std::move(before)), after_(std::move(after)), merge_key_(merge_key) {}
  void redo() override { doc_->applyCorrections(after_); }
  void undo() override { doc_->applyCorrections(before_); }
  int id() const override { return merge_key_ >= 0 ? kMergeCorrection : -1; }
  bool mergeWith(const QUndoCommand* other) override {
    auto* o = dynamic_cast<const CorrectionsCommand*>(other);
    if (!o || o->merge_key_ != merge_key_) return false;
    after_ = o->after_;
    return true;
  }
  static constexpr int kMergeCorrection = 4;

private:
  Document* doc_;
  std::vector<PartCorrection> before_, after_;
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
      part_cache_(std::make_unique<CellPartCache>()) {
  media_ = new Media(this);
  planning_ = new PlanningController(this);
  placement_ = new PlacementSearchJob(this);
  detection_ = new EventDetection(this);
  track_detection_ = new TrackDetection(this);
  steps_ = new StepStatusModel(this);
  connect(&undo_, &QUndoStack::cleanChanged, this, [this] { emit modifiedChanged(isModified()); });
  connect(media_, &Media::edited, this, &Document::setModified);
  connect(media_, &Media::videoChanged, this, [this] {
    clampFrame();
    emit displayChanged();
  });
  connect(planning_, &PlanningController::resultChanged, this, [this] {
    playback_t_ = 0.0;
    if (!planning_->interpolator()) display_mode_ = DisplayMode::Demonstration;
    emit displayChanged();
  });
}

Document::~Document() = default;

// ---------------------------------------------------------------------------------- files

void Document::loadScene(const SceneReference& ref, std::shared_ptr<const Scene>& scene,
                         std::shared_ptr<const BenchmarkTask>& task) const {
  SceneLoadOptions options;
  options.load_visual_meshes = true;
  options.mesh_cache = mesh_cache_.get();
  ReferencedScene loaded = load_referenced_scene(ref, data_dir_, options);
  scene = std::move(loaded.scene);
  task = std::move(loaded.task);
}

std::vector<std::string> Document::newFromBenchmark(const std::string& task_name, const std::string& robot, int pose) {
  SceneReference ref;
  ref.task = task_name;
  ref.robot = robot;
  ref.pose = pose;
  NewProject made = new_benchmark_project(data_dir_, ref);
  std::shared_ptr<const Scene> scene;
  std::shared_ptr<const BenchmarkTask> task;
  loadScene(made.project.scene, scene, task);
  install(std::move(made.project), std::move(scene), std::move(task), QString());
  return made.deck.notes();
}

void Document::newFromCell(const std::string& cell_file) {
  NewProject made = new_cell_project(data_dir_, cell_file);
  std::shared_ptr<const Scene> scene;
  std::shared_ptr<const BenchmarkTask> task;
  loadScene(made.project.scene, scene, task);
  install(std::move(made.project), std::move(scene), std::move(task), QString());
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
                     "lists " + join(p.demonstration.object_ids) + " but the scene " + p.scene.describe() + " has " +
                         join(ids) + " (in this order)");
  }
  install(std::move(p), std::move(scene), std::move(task), QString::fromStdString(path));
}

void Document::install(Project p, std::shared_ptr<const Scene> scene, std::shared_ptr<const BenchmarkTask> task,
                       const QString& file) {
  // The cell as the editor edits it (the scene was built from the same file a moment ago).
  cell_.reset();
  if (p.scene.is_cell()) cell_ = load_cell(p.scene.cell);
  scene_ref_ = p.scene;
  demonstration_ = p.demonstration;
  corrections_ = p.tracker_corrections;
  scene_ = std::move(scene);
  task_ = std::move(task);
  file_ = file;
  template_ = false;
  extra_modified_ = false;
  undo_.clear();
  undo_.setClean();
  selected_event_ = -1;
  selected_object_ = -1;
  selected_furniture_ = -1;
  display_mode_ = DisplayMode::Demonstration;
  playback_t_ = 0.0;
  refreshIssues();
  // Video and camera: a missing or unreadable file is reported on the Video step, not fatal.
  media_->load(p.video, p.camera, p.markers);
  frame_ = p.frame;
  clampFrame();
  planning_->load(p);
  extra_modified_ = false;
  emit projectLoaded();
  emit fileChanged();
  emit demonstrationChanged();
  emit selectionChanged();
  emit currentFrameChanged(frame_);
  emit displayChanged();
  emit modifiedChanged(false);
}

void Document::clampFrame() {
  const int clamped = std::clamp(frame_, 0, std::max(0, frameCount() - 1));
  if (clamped == frame_) return;
  frame_ = clamped;
  emit currentFrameChanged(frame_);
}

Project Document::project() const {
  Project p;
  p.scene = scene_ref_;
  p.video = media_->videoFile();
  p.camera = media_->cameraFile();
  p.markers = media_->markersFile();
  p.demonstration = demonstration_;
  // A part a cell edit removed takes its corrections with it.
  for (const auto& c : corrections_)
    if (demonstration_.object_index(c.id) >= 0) p.tracker_corrections.push_back(c);
  p.planner = planning_->settings();
  p.result = planning_->storedResult();
  p.frame = frame_;
  return p;
}

void Document::writeFiles(const QString& file, Project& p) const {
  const std::string path = QFileInfo(file).absoluteFilePath().toStdString();
  if (p.result) planning_->writePath(path, *p.result);
  save_project(path, p);
}

void Document::save() {
  if (file_.isEmpty() || template_) throw std::logic_error("save: the project has no file of its own yet");
  saveAs(file_);
}

void Document::saveAs(const QString& file) {
  Project p = project();
  writeFiles(file, p);
  if (p.result) planning_->pathWritten(p.result->path);
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
  if (file_.isEmpty()) return tr("Untitled (%1)").arg(q(scene_ref_.is_cell() ? scene_->name : scene_ref_.task));
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

// ------------------------------------------------------------------------------- cell

bool Document::cellIsBundled() const {
  if (!cell_) return false;
  std::error_code ec;
  const auto bundled = std::filesystem::weakly_canonical(std::filesystem::path(data_dir_) / ".." / "cells", ec);
  const auto file = std::filesystem::weakly_canonical(cell_->file, ec);
  const auto rel = file.lexically_relative(bundled);
  return !rel.empty() && *rel.begin() != "..";
}

CellSceneOptions Document::cellSceneOptions() const {
  CellSceneOptions o;
  o.data_dir = data_dir_;
  o.load_visual_meshes = true;
  o.mesh_cache = mesh_cache_.get();
  o.part_cache = part_cache_.get();
  return o;
}

void Document::setMediaFile(Media::File which, const QString& file) {
  const std::string after = file.isEmpty() ? std::string() : QFileInfo(file).absoluteFilePath().toStdString();
  const QString name = file.isEmpty() ? tr("none") : QFileInfo(file).fileName();
  const QString text = which == Media::File::Video    ? tr("Use the video %1").arg(name)
                       : which == Media::File::Camera ? tr("Use the camera calibration %1").arg(name)
                                                      : tr("Use the marker scene %1").arg(name);
  undo_.push(new MediaCommand(media_, which, media_->fileOf(which), after, text));
}

void Document::editCell(const Cell& after, const QString& text, int merge_key) {
  if (!cell_) throw std::logic_error("editCell: the project is not on a cell");
  if (cellIsBundled())
    throw InputError(cell_->file, "", "a bundled example cell is not changed in place: save it under a name of your "
                                      "own first (Save Cell As in the Cell panel)");
  CellCommand::State next{after, nullptr, {}};
  next.scene = std::make_shared<const Scene>(build_cell_scene(after, cellSceneOptions()));
  next.demo = demonstration_for_parts(demonstration_, *next.scene, cell_start_state(after, *next.scene));
  save_cell(after.file, after);  // throws when it cannot be written: then nothing changed
  undo_.push(new CellCommand(this, text, {*cell_, scene_, demonstration_}, std::move(next), merge_key));
}

void Document::applyCell(const Cell& cell, std::shared_ptr<const Scene> scene, const Demonstration& demo, bool write) {
  // The file is where the cell lives now (Save Cell As may have moved it since the edit).
  const std::string file = cell_ ? cell_->file : cell.file;
  cell_ = cell;
  cell_->file = file;
  scene_ = std::move(scene);
  // Undo and redo write the file back, as the edit did; a failure leaves the project modified.
  try {
    if (write) save_cell(file, *cell_);
  } catch (const InputError&) {
    extra_modified_ = true;
  }
  demonstration_ = demo;
  refreshIssues();
  if (selected_object_ >= static_cast<int>(demonstration_.object_ids.size())) selected_object_ = -1;
  if (selected_event_ >= static_cast<int>(demonstration_.events.size())) selected_event_ = -1;
  if (selected_furniture_ >= static_cast<int>(cell_ ? cell_->furniture.size() : 0)) selected_furniture_ = -1;
  emit sceneChanged();
  emit demonstrationChanged();
  emit selectionChanged();
  emit displayChanged();
}

void Document::setRobotBase(const BasePose& base) {
  const QString text = tr("Stand the robot at (%1, %2) m, %3°")
                           .arg(base.x, 0, 'f', 2).arg(base.y, 0, 'f', 2).arg(base.yaw * 180 / M_PI, 0, 'f', 0);
  if (cell_) {
    Cell after = *cell_;
    // The pedestal goes with the robot (scene furniture i is the cell's furniture i).
    if (const int pedestal = robot_pedestal(*scene_); pedestal >= 0) {
      Pose& pose = after.furniture[static_cast<size_t>(pedestal)].pose;
      pose = base.pose() * after.robot.base.inverse() * pose;
    }
    after.robot.base = base.pose();
    editCell(after, text);
    return;
  }
  SceneReference ref = scene_ref_;
  ref.base = base;
  std::shared_ptr<const Scene> scene;
  std::shared_ptr<const BenchmarkTask> task;
  loadScene(ref, scene, task);  // throws, changing nothing, for a robot that cannot be stood there
  undo_.push(new BaseCommand(this, text, {scene_ref_, scene_}, {std::move(ref), std::move(scene)}));
}

void Document::applySceneReference(const SceneReference& ref, std::shared_ptr<const Scene> scene) {
  scene_ref_ = ref;
  scene_ = std::move(scene);
  refreshIssues();  // the robot's deck and support box moved with it
  emit sceneChanged();
  emit displayChanged();
}

void Document::saveCellAs(const QString& file) {
  if (!cell_) throw std::logic_error("saveCellAs: the project is not on a cell");
  const std::string path = QFileInfo(file).absoluteFilePath().toStdString();
  Cell c = *cell_;
  c.file = path;
  if (c.name.empty() || cellIsBundled()) c.name = std::filesystem::path(path).stem().string();
  save_cell(path, c);
  cell_ = c;
  scene_ref_.cell = path;
  setModified();
  emit cellFileChanged();
}

// ------------------------------------------------------------------------------ edits

void Document::refreshIssues() {
  issues_ = validate(demonstration_);
  if (!issues_.empty() || !scene_) return;
  // A part resting on no support fails the validator's placement test on every path: said here,
  // before planning, as the plan job would (a rest within 2 cm of a support is settled onto it).
  for (const UnsupportedRest& r : unsupported_rests(*scene_, settle_on_supports(*scene_, demonstration_)))
    issues_.push_back({r.event, "frame " + std::to_string(r.frame) + ": " + r.message});
}

void Document::applyDemonstration(const Demonstration& demo, int selected_event) {
  demonstration_ = demo;
  refreshIssues();
  const int n = static_cast<int>(demo.events.size());
  selected_event_ = selected_event < n ? selected_event : -1;
  if (selected_event_ >= 0) selected_object_ = demo.events[selected_event_].object;
  emit demonstrationChanged();
  emit selectionChanged();
  emit displayChanged();
}

void Document::pushEdit(const QString& text, const Demonstration& after, int selected_after, int merge_id) {
  long key = -1;
  if (merge_id >= 0) key = static_cast<long>(selected_after) * 4096 + selected_object_;
  undo_.push(new DemoCommand(this, text, demonstration_, after, selected_event_, selected_after, merge_id, key));
}

int Document::addEvent(int frame, int object, EventType type) {
  if (!hasProject() || object < 0 || object >= static_cast<int>(demonstration_.object_ids.size())) return -1;
  Demonstration d = demonstration_;
  const int index = static_cast<int>(insert_event(d, new_event_at(d, frame, object, type)));
  pushEdit(tr("Add %1 of %2 at frame %3").arg(type_word(type), q(d.object_ids[object])).arg(frame), d, index);
  return index;
}

void Document::removeEvent(int index) {
  if (index < 0 || index >= static_cast<int>(demonstration_.events.size())) return;
  Demonstration d = demonstration_;
  const ContactEvent& e = d.events[index];
  const QString text =
      tr("Delete %1 of %2 at frame %3").arg(type_word(e.type), q(d.object_ids[e.object])).arg(e.frame);
  remove_event(d, static_cast<size_t>(index));
  pushEdit(text, d, -1);
}

void Document::moveEvent(int index, int frame) {
  if (index < 0 || index >= static_cast<int>(demonstration_.events.size())) return;
  frame = std::max(0, frame);
  if (demonstration_.events[index].frame == frame) return;
  Demonstration d = demonstration_;
  const ContactEvent& e = d.events[index];
  const QString text = tr("Move %1 of %2 from frame %3 to %4")
                           .arg(type_word(e.type), q(d.object_ids[e.object]))
                           .arg(e.frame)
                           .arg(frame);
  const int to = static_cast<int>(move_event(d, static_cast<size_t>(index), frame));
  pushEdit(text, d, to);
}

void Document::setObjectPose(int event, int object, const Pose& world_pose, int merge_key) {
  const Demonstration& cur = demonstration_;
  if (event < 0 || event >= static_cast<int>(cur.events.size()) || object < 0 ||
      object >= static_cast<int>(cur.object_ids.size()))
    return;
  Demonstration d = cur;
  const std::vector<size_t> events = rest_events(d, static_cast<size_t>(event), object);
  for (size_t i : events) set_object_pose(d, i, object, storedPose(d, event, object, world_pose));
  QString text = tr("Move %1").arg(q(d.object_ids[object]));
  if (events.size() > 1)
    text += tr(" (rest from frame %1 to %2)").arg(d.events[events.front()].frame).arg(d.events[events.back()].frame);
  else
    text += tr(" at frame %1").arg(d.events[event].frame);
  const long key = (static_cast<long>(event) * 4096 + object) * 1024 + merge_key;
  undo_.push(new DemoCommand(this, text, cur, d, selected_event_, selected_event_, merge_key >= 0 ? kMergePose : -1, key));
}

Pose Document::storedPose(const Demonstration& d, int event, int object, const Pose& world_pose) const {
  // The stored pose may be relative to a robot link (objects riding on the KMR's deck).
  const std::string& frame = d.events[event].pose_frame(object);
  if (frame.empty()) return world_pose;
  const int link = scene_->robot.model.link_index(frame);
  if (link < 0) return world_pose;
  return link_pose(scene_->robot.model, initialConfiguration(), scene_->robot.base, link).inverse() * world_pose;
}

int Document::placeStartsFromEstimates(const std::string& csv) {
  const perception::Camera* camera = media_->camera();
  if (!camera || !camera->world_T_camera)
    throw InputError(csv, "", "placing the parts from pose estimates needs the camera's pose in the world: open a "
                              "camera file that gives it");
  if (demonstration_.events.empty())
    throw InputError(csv, "", "the parts' start is their pose at the first event: detect or add an event first");
  const perception::TrackerInit start = perception::tracker_init_from_bop(
      perception::load_bop_csv(csv), demonstration_.object_ids, *camera->world_T_camera, csv);
  if (start.frame != 0)
    throw InputError(csv, "im_id " + std::to_string(start.frame),
                     "the estimates give every part first at frame " + std::to_string(start.frame) +
                         ", and the start is frame 0 (extract --init " + csv + " starts the tracker there)");
  Demonstration d = demonstration_;
  for (const perception::PartStart& part : start.parts) {
    const int object = d.object_index(part.id);
    for (size_t i : rest_events(d, 0, object)) set_object_pose(d, i, object, storedPose(d, 0, object, part.world_T_object));
  }
  pushEdit(tr("Place %n part(s) from pose estimates", nullptr, int(start.parts.size())), d, selected_event_);
  return static_cast<int>(start.parts.size());
}

void Document::setEventConfidence(int event, double confidence) {
  if (event < 0 || event >= static_cast<int>(demonstration_.events.size())) return;
  Demonstration d = demonstration_;
  d.events[event].confidence = std::clamp(confidence, 0.0, 1.0);
  undo_.push(new DemoCommand(this, tr("Set confidence"), demonstration_, d, selected_event_, selected_event_,
                             kMergeConfidence, event));
}

void Document::removeDoubt(int index) {
  if (index < 0 || index >= static_cast<int>(demonstration_.doubts.size())) return;
  Demonstration d = demonstration_;
  const DetectionDoubt& x = d.doubts[index];
  const QString text = tr("Dismiss the doubt on %1 at frames %2-%3")
                           .arg(q(x.object >= 0 && x.object < int(d.object_ids.size()) ? d.object_ids[x.object] : "?"))
                           .arg(x.first_frame)
                           .arg(x.last_frame);
  d.doubts.erase(d.doubts.begin() + index);
  pushEdit(text, d, selected_event_);
}

void Document::replaceDemonstration(const Demonstration& demo, const QString& text) {
  pushEdit(text, demo, -1);
}

// ------------------------------------------------------------------ parts placed again

int Document::correctionAt(int object, int frame) const {
  if (object < 0 || object >= static_cast<int>(demonstration_.object_ids.size())) return -1;
  for (size_t i = 0; i < corrections_.size(); ++i)
    if (corrections_[i].frame == frame && corrections_[i].id == demonstration_.object_ids[object])
      return static_cast<int>(i);
  return -1;
}

int Document::placeAgain(int object) {
  if (!scene_ || frame_ < 1 || object < 0 || object >= static_cast<int>(demonstration_.object_ids.size())) return -1;
  if (const int existing = correctionAt(object, frame_); existing >= 0) return existing;
  const std::string& id = demonstration_.object_ids[object];
  PartCorrection c{id, frame_, demoPosesAt(frame_).at(static_cast<size_t>(object))};
  // Where the tracker last had it is nearer than the demonstration's rest when it drifted.
  if (track_detection_->fromVideo())
    if (const auto tracks = track_detection_->tracks()) {
      const int row = tracks->tracks.object_index(id);
      if (row >= 0) {
        const auto& samples = tracks->tracks.samples[static_cast<size_t>(row)];
        for (int f = std::min(frame_, static_cast<int>(samples.size()) - 1); f >= 0; --f)
          if (samples[static_cast<size_t>(f)].valid) {
            c.world_T_object = samples[static_cast<size_t>(f)].pose;
            break;
          }
      }
    }
  std::vector<PartCorrection> after = corrections_;
  after.push_back(c);
  undo_.push(new CorrectionsCommand(this, tr("Place %1 again at frame %2").arg(q(id)).arg(frame_), corrections_,
                                    after, -1));
  return static_cast<int>(after.size()) - 1;
}

void Document::setCorrectionPose(int index, const Pose& pose, int merge_key) {
  if (index < 0 || index >= static_cast<int>(corrections_.size())) return;
  std::vector<PartCorrection> after = corrections_;
  after[static_cast<size_t>(index)].world_T_object = pose;
  const PartCorrection& c = after[static_cast<size_t>(index)];
  undo_.push(new CorrectionsCommand(this, tr("Move %1 placed again at frame %2").arg(q(c.id)).arg(c.frame),
                                    corrections_, after, merge_key >= 0 ? index * 1024L + merge_key : -1));
}

void Document::removeCorrection(int index) {
  if (index < 0 || index >= static_cast<int>(corrections_.size())) return;
  std::vector<PartCorrection> after = corrections_;
  const PartCorrection c = after[static_cast<size_t>(index)];
  after.erase(after.begin() + index);
  undo_.push(new CorrectionsCommand(this, tr("Remove %1's placement at frame %2").arg(q(c.id)).arg(c.frame),
                                    corrections_, after, -1));
}

void Document::applyCorrections(const std::vector<PartCorrection>& corrections) {
  corrections_ = corrections;
  emit correctionsChanged();
  emit displayChanged();
}

// ------------------------------------------------------------------ selection and time

void Document::selectEvent(int index) {
  const int n = static_cast<int>(demonstration_.events.size());
  if (index >= n) index = -1;
  const bool changed = index != selected_event_;
  selected_event_ = index;
  if (index >= 0) selected_object_ = demonstration_.events[index].object;
  if (changed || index >= 0) emit selectionChanged();
  if (index >= 0) setCurrentFrame(demonstration_.events[index].frame);
}

void Document::selectFurniture(int index) {
  if (!cell_ || index >= static_cast<int>(cell_->furniture.size())) index = -1;
  if (index == selected_furniture_) return;
  selected_furniture_ = index;
  if (index >= 0) selected_object_ = -1;
  emit selectionChanged();
  emit displayChanged();
}

bool Document::moveFurniture(int index, const Pose& pose, int merge_key, QString* error) {
  if (!cell_ || index < 0 || index >= static_cast<int>(cell_->furniture.size())) return false;
  Cell after = *cell_;
  after.furniture[static_cast<size_t>(index)].pose = pose;
  try {
    editCell(after, tr("Move %1").arg(q(after.furniture[static_cast<size_t>(index)].name)), merge_key);
  } catch (const InputError& e) {
    if (error) *error = QString::fromUtf8(e.what());
    return false;
  }
  return true;
}

void Document::selectObject(int object) {
  if (object >= static_cast<int>(demonstration_.object_ids.size())) object = -1;
  if (object == selected_object_ && (object < 0 || selected_furniture_ < 0)) return;
  selected_object_ = object;
  if (object >= 0) selected_furniture_ = -1;
  emit selectionChanged();
  emit displayChanged();
}

int Document::editEvent() const {
  const auto& events = demonstration_.events;
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
  if (const perception::VideoReader* v = media_->video()) return std::max(1, v->frame_count());
  int n = task_ ? task_->frames : 1;
  for (const auto& e : demonstration_.events) n = std::max(n, e.frame + 1);
  return std::max(1, n);
}

double Document::fps() const {
  if (const perception::VideoReader* v = media_->video(); v && v->fps() > 0) return v->fps();
  return demonstration_.fps > 0 ? demonstration_.fps : 30.0;
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
  // Before the first event is there, the parts are where the scene starts them.
  if (demonstration_.events.empty()) {
    if (cell_) return cell_start_state(*cell_, *scene_).objects;
    if (task_) return benchmark_start_state(*task_, *scene_).objects;
  }
  return demo_poses_at_frame(*scene_, demonstration_, frame, initialConfiguration());
}

SceneState Document::displayState() const {
  SceneState s;
  if (!scene_) return s;
  if (display_mode_ == DisplayMode::Result && planning_->interpolator()) return planning_->interpolator()->at(playback_t_);
  s.q = initialConfiguration();
  s.objects = demoPosesAt(frame_);
  // A part placed again here is shown where it was placed (the gizmo moves it there).
  for (size_t o = 0; o < s.objects.size(); ++o)
    if (const int c = correctionAt(static_cast<int>(o), frame_); c >= 0)
      s.objects[o] = corrections_[static_cast<size_t>(c)].world_T_object;
  return s;
}

}  // namespace demoplan::ui
