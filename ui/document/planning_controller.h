#pragma once
// The Plan step of the open project: the planner settings, the background plan job (PlanRunner)
// and the last result with its path, held apart from the project's edits (Document) as Kdenlive
// keeps its timeline model apart from its views. Whether the result still fits the
// demonstration is told by a digest, so edits never re-plan by themselves.
#include <QObject>
#include <memory>
#include <optional>

#include "core/path/path_interpolation.h"
#include "core/project/project.h"
#include "ui/document/plan_runner.h"

namespace demoplan::ui {

class Document;

// The last planning result held in memory: the summary the project stores, the path, and for a
// run of this session what the planner panel explains (why not, where the trees grew).
struct PlanResultData {
  ResultSummary summary;
  std::optional<Path> path;  // absent when planning failed or the path file is missing
  std::vector<std::string> unsampled_transitions;
  std::string infeasible_picks;  // one line per pick that cannot be done from this base pose
  std::vector<std::string> state_names;
  std::vector<size_t> state_nodes;
  std::string shortcut_note;
  std::string regrasp;  // a regrasp the planner added to the demonstration (regrasp.h)
  bool cancelled = false;
  // The scene it was planned in, for identity only (a cell edit makes another scene).
  const Scene* planned_in = nullptr;
};

class PlanningController : public QObject {
  Q_OBJECT
public:
  explicit PlanningController(Document* doc);

  const PlannerSettings& settings() const { return settings_; }
  void setSettings(const PlannerSettings& settings);
  PlanRunner* runner() { return &runner_; }
  const PlanRunner* runner() const { return &runner_; }
  bool isRunning() const { return runner_.isRunning(); }
  // False when the demonstration has issues or a job runs.
  bool start();
  const PlanResultData* result() const { return result_.get(); }
  // The demonstration or the scene (a cell edit) changed since the result was planned.
  bool resultStale() const;
  const PathInterpolator* interpolator() const { return interpolator_.get(); }
  void clear();

  // ---- the project file (Document calls these)
  // A loaded project's settings and stored result (its path file is read and checked here).
  void load(const Project& project);
  // The result to store (none after a cancel).
  std::optional<ResultSummary> storedResult() const;
  // Writes the path beside the project file `file` and points `result` at it.
  void writePath(const std::string& file, ResultSummary& result) const;
  void pathWritten(const std::string& path_file);

signals:
  void settingsChanged();
  void resultChanged();

private:
  void onFinished(const PlanOutcome& outcome);
  void onCancelled(const PlanSnapshot& last);
  void setResult(std::shared_ptr<const PlanResultData> result);
  void interpolatePath();

  Document* doc_;
  const Scene* planning_scene_ = nullptr;  // of the running job
  PlannerSettings settings_;
  PlanRunner runner_;
  std::shared_ptr<const PlanResultData> result_;
  std::unique_ptr<PathInterpolator> interpolator_;
};

}  // namespace demoplan::ui
