#include "ui/document/planning_controller.h"

#include <filesystem>

#include "core/error.h"
#include "ui/document/document.h"

namespace demoplan::ui {

PlanningController::PlanningController(Document* doc) : QObject(doc), doc_(doc), runner_(this) {
  connect(&runner_, &PlanRunner::finished, this, &PlanningController::onFinished);
  connect(&runner_, &PlanRunner::cancelled, this, &PlanningController::onCancelled);
  // The interpolator holds the scene it was made with: remake it in the new one.
  connect(doc_, &Document::sceneChanged, this, [this] {
    interpolatePath();
    emit resultChanged();
  });
}

void PlanningController::setSettings(const PlannerSettings& s) {
  settings_ = s;
  doc_->setModified();
  emit settingsChanged();
}

bool PlanningController::start() {
  if (!doc_->hasProject() || runner_.isRunning() || !doc_->issues().empty()) return false;
  PlanJob job;
  job.scene = doc_->sharedScene();
  job.demonstration = doc_->demonstration();
  job.settings = settings_;
  if (!doc_->sceneReference().is_cell()) {  // a path on a cell names no benchmark task
    job.task = doc_->sceneReference().task;
    job.robot = doc_->sceneReference().robot;
    job.robot_pose = doc_->sceneReference().pose;
  }
  planning_scene_ = job.scene.get();
  return runner_.start(std::move(job));
}

void PlanningController::setResult(std::shared_ptr<const PlanResultData> result) {
  result_ = std::move(result);
  interpolatePath();
}

void PlanningController::interpolatePath() {
  interpolator_.reset();
  // A path stays drawable after a cell edit while it moves the same parts.
  if (result_ && result_->path && result_->path->object_ids == doc_->demonstration().object_ids)
    interpolator_ = std::make_unique<PathInterpolator>(doc_->scene(), *result_->path);
}

void PlanningController::onFinished(const PlanOutcome& o) {
  auto r = std::make_shared<PlanResultData>();
  if (!o.error.empty()) {
    r->summary.message = o.error;
  } else {
    const PlanReport& report = o.report;
    r->summary = summarize(report, o.validated_against);
    r->unsampled_transitions = report.plan.unsampled_transitions;
    if (report.feasibility) r->infeasible_picks = report.feasibility->summary(doc_->scene());
    r->state_nodes = report.plan.state_nodes;
    r->cancelled = report.plan.cancelled;
    r->regrasp = report.plan.regrasp;
    // The unguided planner, and the guided one with a regrasp, plan in states of their making.
    if (const auto& graph = report.plan.graph ? report.plan.graph : o.graph)
      for (const auto& st : graph->states) r->state_names.push_back(st.name);
    if (!report.shortcut_rejection.empty()) r->shortcut_note = "shortened path dropped: " + report.shortcut_rejection;
    if (report.solved()) r->path = report.path;
  }
  r->summary.demonstration_digest = demonstration_digest(doc_->demonstration());
  r->planned_in = planning_scene_;
  setResult(r);
  doc_->setModified();
  emit resultChanged();
}

void PlanningController::onCancelled(const PlanSnapshot& last) {
  if (result_) return;  // the previous result stays
  auto r = std::make_shared<PlanResultData>();
  r->summary.message = "cancelled after " + std::to_string(last.iterations) + " iterations";
  r->summary.iterations = last.iterations;
  r->summary.trees = last.trees;
  r->summary.nodes = last.nodes;
  r->summary.planning_time_s = last.elapsed_s;
  r->cancelled = true;
  r->state_nodes = last.state_nodes;
  setResult(r);
  emit resultChanged();
}

bool PlanningController::resultStale() const {
  return result_ && !result_->cancelled &&
         (result_->summary.demonstration_digest != demonstration_digest(doc_->demonstration()) ||
          result_->planned_in != doc_->sharedScene().get());
}

void PlanningController::clear() {
  setResult(nullptr);
  doc_->setModified();
  emit resultChanged();
}

void PlanningController::load(const Project& project) {
  settings_ = project.planner;
  std::shared_ptr<PlanResultData> r;
  if (project.result) {
    r = std::make_shared<PlanResultData>();
    r->summary = *project.result;
    if (!r->summary.path.empty()) {
      try {
        Path path = load_path(r->summary.path);
        if (path.object_ids != project.demonstration.object_ids || path.robot != project.scene.robot ||
            path.robot_pose != project.scene.pose)
          throw InputError(r->summary.path, "", "was planned for another scene");
        r->path = std::move(path);
      } catch (const std::exception& e) {
        r->summary.message = std::string("the path file cannot be read: ") + e.what();
        r->summary.valid = false;
      }
    }
  }
  if (r) r->planned_in = doc_->sharedScene().get();
  setResult(r);
  emit settingsChanged();
  emit resultChanged();
}

std::optional<ResultSummary> PlanningController::storedResult() const {
  if (result_ && !result_->cancelled) return result_->summary;
  return std::nullopt;
}

void PlanningController::writePath(const std::string& file, ResultSummary& result) const {
  if (!result_ || !result_->path) return;
  std::filesystem::path result_file(file);
  result_file.replace_extension(".path.json");
  save_path(result_file.string(), *result_->path);
  result.path = result_file.string();
}

void PlanningController::pathWritten(const std::string& path_file) {
  if (!result_) return;
  auto r = std::make_shared<PlanResultData>(*result_);
  r->summary.path = path_file;
  result_ = r;  // the same path: the interpolator stays
}

}  // namespace demoplan::ui
