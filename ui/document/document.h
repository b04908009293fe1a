#pragma once
// The open project as the whole UI sees it: the project file, the scene it refers to (loaded
// with visual meshes), the demonstration with an undo stack for every edit, the selection and
// the playhead. What belongs to one step lives in its own part, owned here: the recording
// (Media), event detection in the video (EventDetection) and from the task's pose tracks
// (TrackDetection), planning and its result (PlanningController), and
// how each step stands (StepStatusModel). Widgets read from these and change them only through
// their methods; signals tell them what changed.
#include <QObject>
#include <QString>
#include <QUndoStack>
#include <memory>
#include <optional>

#include "core/cell/cell.h"
#include "core/cell/cell_scene.h"
#include "core/demo/part_correction.h"
#include "core/demo/benchmark_scene.h"
#include "core/project/project.h"
#include "ui/document/event_detection.h"
#include "ui/document/media.h"
#include "ui/document/placement_search_job.h"
#include "ui/document/planning_controller.h"
#include "ui/document/step_status.h"
#include "ui/document/track_detection.h"

namespace demoplan::ui {

class Document : public QObject {
  Q_OBJECT
public:
  explicit Document(std::string default_data_dir, QObject* parent = nullptr);
  ~Document() override;

  // ---- the parts
  Media* media() { return media_; }
  const Media* media() const { return media_; }
  EventDetection* detection() { return detection_; }
  TrackDetection* trackDetection() { return track_detection_; }
  PlanningController* planning() { return planning_; }
  const PlanningController* planning() const { return planning_; }
  PlacementSearchJob* placement() { return placement_; }
  const PlacementSearchJob* placement() const { return placement_; }
  StepStatusModel* steps() { return steps_; }
  const StepStatusModel* steps() const { return steps_; }

  // ---- files (throw InputError naming file and field; the document is unchanged on error)
  // Returns one line per object riding on the robot's deck (waiter): where it rides and why.
  std::vector<std::string> newFromBenchmark(const std::string& task, const std::string& robot, int pose);
  // A new project on a cell file (docs/cell.md): its parts, no event yet. Throws InputError.
  void newFromCell(const std::string& cell_file);
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
  // Takes the project as it stands now (demonstration, files, settings, result, playhead).
  Project project() const;

  // ---- scene
  const std::string& dataDir() const { return data_dir_; }
  const Scene& scene() const { return *scene_; }
  std::shared_ptr<const Scene> sharedScene() const { return scene_; }
  // The benchmark task the scene comes from; null for a cell.
  const BenchmarkTask* task() const { return task_.get(); }
  const SceneReference& sceneReference() const { return scene_ref_; }

  // ---- the cell of a project on a cell file (null otherwise), edited in the Cell panel
  const Cell* cell() const { return cell_ ? &*cell_ : nullptr; }
  // A bundled example cell is not edited in place: saveCellAs first.
  bool cellIsBundled() const;
  // Replaces the cell as one undoable step (consecutive edits with the same merge_key >= 0, one
  // field's spin steps, are one step): the scene is rebuilt, the demonstration follows the
  // parts (demonstration_for_parts) and the cell file is written at once, so the file always
  // holds what the editor shows (undo writes it back). Throws InputError and changes nothing
  // when the scene cannot be built, a removed part has events, or the file cannot be written.
  void editCell(const Cell& after, const QString& text, int merge_key = -1);
  // The operator chooses another video, camera calibration or marker scene (empty: none): one
  // undo step, undone by going back to the file before. A file that cannot be read is still
  // taken (its error shown on the Video step), so the operator can undo it.
  void setMediaFile(Media::File which, const QString& file);
  // Writes the cell to `file` (relative paths follow) and refers the project to it.
  void saveCellAs(const QString& file);
  // How the document builds cell scenes: its data folder, visual meshes, and the caches shared
  // by every rebuild (meshes, and the parts' placements and handles).
  CellSceneOptions cellSceneOptions() const;
  // Stands the robot at `base` (the placement search's choice), one undo step: a task's robot
  // with its support box made for the new base, a cell's robot in the cell file. Throws
  // InputError, changing nothing, for a mobile robot or a cell that cannot be written.
  void setRobotBase(const BasePose& base);
  // Used by the undo command of setRobotBase.
  void applySceneReference(const SceneReference& ref, std::shared_ptr<const Scene> scene);
  // Used by the undo commands; `write`: the cell file does not hold `cell` yet.
  void applyCell(const Cell& cell, std::shared_ptr<const Scene> scene, const Demonstration& demo, bool write);

  // ---- demonstration and edits (every edit goes through the undo stack)
  const Demonstration& demonstration() const { return demonstration_; }
  const std::vector<DemonstrationIssue>& issues() const { return issues_; }
  QUndoStack* undoStack() { return &undo_; }
  int addEvent(int frame, int object, EventType type);  // returns its index
  void removeEvent(int index);
  void moveEvent(int index, int frame);
  // The pose of `object` at `event`, in world coordinates (metres); applies to every event of
  // the same rest (demo_poses.h). Consecutive edits with the same `merge_key` (>= 0: one
  // field's spin steps, one gizmo drag) of the same part and event are one undo step.
  void setObjectPose(int event, int object, const Pose& world_pose, int merge_key = -1);
  // Places every part where a pose estimator's BOP results CSV shows it in frame 0 (its start
  // rest; one undo step), as the operator would with the gizmo. Returns how many; throws
  // InputError naming the file (no camera pose, no event yet, a part without an estimate at
  // frame 0, the file itself) and changes nothing then.
  int placeStartsFromEstimates(const std::string& csv);
  void setEventConfidence(int event, double confidence);
  // Dismisses a detection doubt (Demonstration::doubts) once the operator has checked it.
  void removeDoubt(int index);
  // Replaces the whole demonstration (as one undoable step).
  void replaceDemonstration(const Demonstration& demo, const QString& text);
  // Used by the undo commands.
  void applyDemonstration(const Demonstration& demo, int selected_event);

  // ---- parts placed again for the part-model tracker (the project's tracker_corrections): where
  // the tracker lost a part or followed it wrongly, the operator places it over a later frame of
  // the video as over the start frame, and Detect Events takes it from there.
  const std::vector<PartCorrection>& corrections() const { return corrections_; }
  // The correction of `object` at `frame`; -1 when there is none.
  int correctionAt(int object, int frame) const;
  // Places `object` again at the playhead (one undo step), where the last detection in the video
  // last measured it (at or before the playhead), else where the demonstration shows it there.
  // Returns the correction's index (an existing one at this frame is returned as it is), or -1 at
  // frame 0 (the start: placed by moving the part there) or without such a part.
  int placeAgain(int object);
  // Moves a correction (one undo step; consecutive edits with the same merge_key >= 0 merge).
  void setCorrectionPose(int index, const Pose& pose, int merge_key = -1);
  void removeCorrection(int index);
  // Used by the undo command.
  void applyCorrections(const std::vector<PartCorrection>& corrections);

  // ---- selection and time
  int selectedEvent() const { return selected_event_; }
  int selectedObject() const { return selected_object_; }
  // A cell's furniture chosen in the Cell panel (index into cell()->furniture; -1 none): the 3D
  // view's gizmo moves it. Selecting a part clears it and the other way round.
  int selectedFurniture() const { return selected_furniture_; }
  void selectFurniture(int index);
  // The gizmo's drag: the furniture at `pose`, one undo step per drag (merge_key as editCell's).
  // False, with the reason in `error`, when the cell refuses it (a bundled example, say).
  bool moveFurniture(int index, const Pose& pose, int merge_key, QString* error = nullptr);
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

signals:
  void projectLoaded();
  void demonstrationChanged();
  void selectionChanged();
  void currentFrameChanged(int frame);
  void displayChanged();  // the display state changed (frame, playback, pose edit, result)
  void modifiedChanged(bool modified);
  void fileChanged();
  void saved(const QString& file);
  void sceneChanged();  // the same project on another scene: a cell edit, its undo or redo
  void cellFileChanged();
  void correctionsChanged();

private:
  // validate()'s rules, then the rests no support holds (supported_rests.h).
  void refreshIssues();
  void loadScene(const SceneReference& ref, std::shared_ptr<const Scene>& scene,
                 std::shared_ptr<const BenchmarkTask>& task) const;
  void install(Project project, std::shared_ptr<const Scene> scene, std::shared_ptr<const BenchmarkTask> task,
               const QString& file);
  void writeFiles(const QString& file, Project& p) const;
  void pushEdit(const QString& text, const Demonstration& after, int selected_after, int merge_id = -1);
  void clampFrame();
  // `world_pose` as `d` stores it for `object` at `event` (relative to a robot link it rides on).
  Pose storedPose(const Demonstration& d, int event, int object, const Pose& world_pose) const;

  std::string data_dir_;
  std::unique_ptr<MeshCache> mesh_cache_;
  std::unique_ptr<CellPartCache> part_cache_;
  SceneReference scene_ref_;
  Demonstration demonstration_;
  std::vector<PartCorrection> corrections_;
  QString file_;
  bool template_ = false;
  bool extra_modified_ = false;
  std::shared_ptr<const Scene> scene_;
  std::shared_ptr<const BenchmarkTask> task_;
  std::optional<Cell> cell_;
  std::vector<DemonstrationIssue> issues_;
  QUndoStack undo_;
  int selected_event_ = -1;
  int selected_object_ = -1;
  int frame_ = 0;
  DisplayMode display_mode_ = DisplayMode::Demonstration;
  double playback_t_ = 0.0;
  // Children of this QObject, made in the constructor in this order.
  Media* media_ = nullptr;
  int selected_furniture_ = -1;
  PlanningController* planning_ = nullptr;
  PlacementSearchJob* placement_ = nullptr;
  EventDetection* detection_ = nullptr;
  TrackDetection* track_detection_ = nullptr;
  StepStatusModel* steps_ = nullptr;
};

}  // namespace demoplan::ui
