#pragma once
// The open project as the whole UI sees it: the project data, the scene it refers to (loaded
// with visual meshes), the demonstration with an undo stack for every edit, the selection, the
// playhead, the video and camera, the planner and its last result. Widgets read from it and
// change it only through its methods; it tells them what changed through signals.
#include <QObject>
#include <QString>
#include <QUndoStack>
#include <memory>
#include <optional>

#include "core/demo/benchmark_scene.h"
#include "core/planning/path_interpolation.h"
#include "ui/document/extraction_runner.h"
#include "ui/document/plan_runner.h"
#include "ui/project/project.h"

namespace demoplan::perception {
class VideoReader;
struct Camera;
}  // namespace demoplan::perception

namespace demoplan::ui {

// The last planning result held in memory: the summary the project stores, and the path.
struct PlanResultData {
  ResultSummary summary;
  std::optional<Path> path;  // absent when planning failed or the path file is missing
  std::vector<std::string> unsampled_transitions;
  std::string infeasible_picks;  // one line per pick that cannot be done from this base pose
  std::vector<std::string> state_names;
  std::vector<size_t> state_nodes;
  std::string shortcut_note;
  bool cancelled = false;
};

// One step of the operator's job (UX.md), with how it stands.
enum class Step { Video = 0, Events, Poses, Plan, Export };
enum class StepStatus { None, Ok, Warning, Error, Busy };
struct StepState {
  StepStatus status = StepStatus::None;
  QString message;  // one line: what is wrong and what to do next
};

class Document : public QObject {
  Q_OBJECT
public:
  explicit Document(std::string default_data_dir, QObject* parent = nullptr);
  ~Document() override;

  // ---- files (throw InputError naming file and field; the document is unchanged on error)
  // Returns one line per object riding on the robot's deck (waiter): where it rides and why.
  std::vector<std::string> newFromBenchmark(const std::string& task, const std::string& robot, int pose);
  void open(const QString& file);
  void save();                        // to filePath(); throws when it is empty or a template
  void saveAs(const QString& file);
  void saveCopy(const QString& file) const;  // autosave: writes without changing the file path
  // Whether a project is loaded.
  bool hasProject() const { return scene_ != nullptr; }
  QString filePath() const { return file_; }
  QString displayName() const;
  // A read-only template (the bundled sample): Save asks where to save.
  bool isTemplate() const { return template_; }
  void setTemplate(bool t);
  // Where Save writes (a recovered autosave goes back to its original file).
  void setFilePath(const QString& file);
  bool isModified() const;
  void setModified();                 // a change outside the undo stack
  // Takes the project as it stands now (demonstration, settings, playhead).
  Project project() const;

  // ---- scene
  const std::string& dataDir() const { return data_dir_; }
  const Scene& scene() const { return *scene_; }
  std::shared_ptr<const Scene> sharedScene() const { return scene_; }
  const BenchmarkTask& task() const { return *task_; }
  const SceneReference& sceneReference() const { return project_.scene; }

  // ---- demonstration and edits (every edit goes through the undo stack)
  const Demonstration& demonstration() const { return project_.demonstration; }
  const std::vector<DemonstrationIssue>& issues() const { return issues_; }
  QUndoStack* undoStack() { return &undo_; }
  int addEvent(int frame, int object, EventType type);  // returns its index
  void removeEvent(int index);
  void moveEvent(int index, int frame);
  // The pose of `object` at `event`, in world coordinates (metres); applies to every event of
  // the same rest (demo_poses.h). Consecutive edits with the same `merge_key` (>= 0: one
  // field's spin steps, one gizmo drag) of the same part and event are one undo step.
  void setObjectPose(int event, int object, const Pose& world_pose, int merge_key = -1);
  void setEventConfidence(int event, double confidence);
  // Replaces the whole demonstration (as one undoable step).
  void replaceDemonstration(const Demonstration& demo, const QString& text);
  // Used by the undo commands.
  void applyDemonstration(const Demonstration& demo, int selected_event);

  // ---- selection and time
  int selectedEvent() const { return selected_event_; }
  int selectedObject() const { return selected_object_; }
  void selectEvent(int index);  // also selects its object and moves the playhead to it
  void selectObject(int object);
  // The event the pose editor edits: the selected one, else the last at or before the playhead.
  int editEvent() const;
  int currentFrame() const { return frame_; }
  void setCurrentFrame(int frame);
  int frameCount() const;
  double fps() const;
  // What the 3D view and the video overlay show.
  enum class DisplayMode { Demonstration, Result };
  DisplayMode displayMode() const { return display_mode_; }
  double playbackT() const { return playback_t_; }
  void setPlaybackT(double t);  // switches to Result mode
  void showDemonstration();     // switches back to Demonstration mode
  SceneState displayState() const;
  Eigen::VectorXd initialConfiguration() const;
  PoseList demoPosesAt(double frame) const;

  // ---- video and camera
  QString videoPath() const { return QString::fromStdString(project_.video); }
  QString cameraPath() const { return QString::fromStdString(project_.camera); }
  void setVideo(const QString& file);   // opens it; the error is in videoError()
  void setCamera(const QString& file);  // loads it; the error is in cameraError()
  perception::VideoReader* video() const { return video_.get(); }
  const perception::Camera* camera() const { return camera_.get(); }
  QString videoError() const { return video_error_; }
  QString cameraError() const { return camera_error_; }
  // The marker scene (which ArUco markers are on which part), to detect the events in the video.
  QString markersPath() const { return QString::fromStdString(project_.markers); }
  void setMarkers(const QString& file);

  // ---- event detection (perception): replaces the demonstration as one undoable edit
  ExtractionRunner* extractor() { return &extractor_; }
  // What is missing to detect events; empty when startExtraction() can run.
  QString extractionBlocker() const;
  bool startExtraction();

  // ---- planning
  const PlannerSettings& plannerSettings() const { return project_.planner; }
  void setPlannerSettings(const PlannerSettings& s);
  PlanRunner* planner() { return &runner_; }
  bool startPlanning();  // false when the demonstration has issues or a job runs
  const PlanResultData* result() const { return result_.get(); }
  bool resultStale() const;
  const PathInterpolator* interpolator() const { return interpolator_.get(); }
  void clearResult();

  // ---- the five steps
  StepState stepState(Step step) const;
  void markExported(const QString& file);

signals:
  void projectLoaded();
  void demonstrationChanged();
  void selectionChanged();
  void currentFrameChanged(int frame);
  void displayChanged();  // the display state changed (frame, playback, pose edit)
  void modifiedChanged(bool modified);
  void fileChanged();
  void videoChanged();
  void cameraChanged();
  void plannerSettingsChanged();
  void resultChanged();
  void stepsChanged();
  void saved(const QString& file);
  void extractionDone(const ExtractionOutcome& outcome);

private:
  void loadScene(const SceneReference& ref, std::shared_ptr<const Scene>& scene,
                 std::shared_ptr<const BenchmarkTask>& task) const;
  void install(Project project, std::shared_ptr<const Scene> scene, std::shared_ptr<const BenchmarkTask> task,
               const QString& file);
  void onPlanFinished(const PlanOutcome& outcome);
  void loadResultPath();
  void writeFiles(const QString& file, Project& p) const;
  void pushEdit(const QString& text, const Demonstration& after, int selected_after, int merge_id = -1);

  std::string data_dir_;
  std::unique_ptr<MeshCache> mesh_cache_;
  Project project_;
  QString file_;
  bool template_ = false;
  bool extra_modified_ = false;
  std::shared_ptr<const Scene> scene_;
  std::shared_ptr<const BenchmarkTask> task_;
  std::vector<DemonstrationIssue> issues_;
  QUndoStack undo_;
  int selected_event_ = -1;
  int selected_object_ = -1;
  int frame_ = 0;
  DisplayMode display_mode_ = DisplayMode::Demonstration;
  double playback_t_ = 0.0;
  std::unique_ptr<perception::VideoReader> video_;
  std::unique_ptr<perception::Camera> camera_;
  QString video_error_, camera_error_;
  PlanRunner runner_;
  ExtractionRunner extractor_;
  std::shared_ptr<const PlanResultData> result_;
  std::unique_ptr<PathInterpolator> interpolator_;
  QString exported_to_;
};

}  // namespace demoplan::ui
