#include "ui/document/step_status.h"

#include <QFileInfo>

#include "core/graph/constraint_graph.h"
#include "perception/camera/camera_model.h"
#include "perception/video/video_reader.h"
#include "ui/document/document.h"

namespace demoplan::ui {

namespace {
QString q(const std::string& s) { return QString::fromStdString(s); }
}  // namespace

StepStatusModel::StepStatusModel(Document* doc) : QObject(doc), doc_(doc) {
  auto all = [this] {
    refreshPoses();
    refresh();
  };
  auto others = [this] { refresh(); };
  connect(doc_, &Document::projectLoaded, this, [this, all] {
    exported_to_.clear();
    all();
  });
  connect(doc_, &Document::demonstrationChanged, this, all);
  connect(doc_->media(), &Media::videoChanged, this, others);
  connect(doc_->media(), &Media::cameraChanged, this, others);
  connect(doc_->media(), &Media::markersChanged, this, others);
  PlanningController* planning = doc_->planning();
  connect(planning->runner(), &PlanRunner::started, this, others);
  connect(planning, &PlanningController::resultChanged, this, others);
  connect(planning->runner(), &PlanRunner::cancelled, this, others);
  connect(doc_->detection(), &EventDetection::done, this, others);
}

void StepStatusModel::markExported(const QString& file) {
  exported_to_ = file;
  refresh();
}

void StepStatusModel::refresh() {
  states_[size_t(Step::Video)] = video();
  states_[size_t(Step::Events)] = events();
  states_[size_t(Step::Plan)] = plan();
  states_[size_t(Step::Export)] = exported();
  emit changed();
}

void StepStatusModel::refreshPoses() {
  StepState& s = states_[size_t(Step::Poses)];
  if (!doc_->hasProject()) {
    s = {StepStatus::None, tr("Open a project (File > Open) or the sample")};
  } else if (!doc_->issues().empty()) {
    s = {StepStatus::None, tr("Fix the events first")};
  } else {
    try {
      ++graph_builds_;
      const ConstraintGraph g = build_constraint_graph(doc_->scene(), doc_->demonstration());
      s = {StepStatus::Ok, tr("%1 placements and %2 grasp states")
                               .arg(g.states_of_kind(StateKind::Placement).size())
                               .arg(g.states_of_kind(StateKind::Grasp).size())};
    } catch (const std::exception& e) {
      s = {StepStatus::Error, QString::fromUtf8(e.what())};
    }
  }
}

StepState StepStatusModel::video() const {
  if (!doc_->hasProject()) return {StepStatus::None, tr("Open a project (File > Open) or the sample")};
  const Media& m = *doc_->media();
  if (!m.videoError().isEmpty())
    return {StepStatus::Error, m.videoError() + tr(" — File > Open Video… to locate the recording")};
  if (!m.video())
    return {StepStatus::Warning,
            tr("No video: the events come from the benchmark's labels. File > Open Video… adds the recording")};
  QString msg = tr("%1: %2 frames at %3 fps")
                    .arg(QFileInfo(m.videoPath()).fileName())
                    .arg(m.video()->frame_count())
                    .arg(m.video()->fps(), 0, 'g', 3);
  if (!m.cameraError().isEmpty()) return {StepStatus::Warning, msg + tr("; camera: ") + m.cameraError()};
  if (!m.camera()) return {StepStatus::Warning, msg + tr("; no camera calibration: outlines cannot be drawn")};
  if (!m.camera()->world_T_camera)
    return {StepStatus::Warning, msg + tr("; the camera has no pose in the world: outlines cannot be drawn")};
  return {StepStatus::Ok, msg + tr("; camera calibrated")};
}

StepState StepStatusModel::events() const {
  if (!doc_->hasProject()) return {StepStatus::None, tr("Open a project (File > Open) or the sample")};
  const auto& issues = doc_->issues();
  if (!issues.empty()) {
    QString msg = q(issues.front().message);
    if (issues.size() > 1) msg += tr(" (and %1 more)").arg(issues.size() - 1);
    return {StepStatus::Error, msg};
  }
  const Demonstration& d = doc_->demonstration();
  int low = 0;
  for (const auto& e : d.events) low += e.confidence < kLowConfidence;
  if (low > 0)
    return {StepStatus::Warning, tr("%1 event(s) below %2% confidence: check them").arg(low).arg(kLowConfidence * 100)};
  if (!d.doubts.empty())
    return {StepStatus::Warning, tr("%1 detection doubt(s), hatched on the timeline: check the events there (Ctrl+Shift+J), "
                                    "then dismiss them").arg(d.doubts.size())};
  return {StepStatus::Ok, tr("%1 events on %2 parts, all rules hold").arg(d.events.size()).arg(d.object_ids.size())};
}

StepState StepStatusModel::plan() const {
  if (!doc_->hasProject()) return {StepStatus::None, tr("Open a project (File > Open) or the sample")};
  const PlanningController& planning = *doc_->planning();
  if (planning.isRunning()) return {StepStatus::Busy, tr("Planning…")};
  const PlanResultData* r = planning.result();
  if (!r) return {StepStatus::None, tr("Not planned yet: press Plan (F5)")};
  const ResultSummary& s = r->summary;
  if (r->cancelled) return {StepStatus::Warning, tr("Cancelled: ") + q(s.message)};
  if (planning.resultStale()) return {StepStatus::Warning, tr("The demonstration changed since the last plan: plan again")};
  if (!s.solved && !r->infeasible_picks.empty()) {
    const std::string first = r->infeasible_picks.substr(0, r->infeasible_picks.find(':'));
    return {StepStatus::Error, tr("No path: %1 from this robot base pose (see the Planner panel)").arg(q(first))};
  }
  if (!s.solved) return {StepStatus::Error, tr("No path: ") + q(s.message)};
  if (!s.valid) return {StepStatus::Warning, tr("The validator rejects the path: ") + q(s.message)};
  return {StepStatus::Ok, tr("Valid path found in %1 s").arg(s.planning_time_s, 0, 'f', 2)};
}

StepState StepStatusModel::exported() const {
  if (!doc_->hasProject()) return {StepStatus::None, tr("Open a project (File > Open) or the sample")};
  if (!exported_to_.isEmpty()) return {StepStatus::Ok, tr("Exported to %1").arg(exported_to_)};
  const PlanningController& planning = *doc_->planning();
  const PlanResultData* r = planning.result();
  if (r && r->path && r->summary.valid && !planning.resultStale())
    return {StepStatus::None, tr("Ready to export: File > Export Program… (Ctrl+E)")};
  return {StepStatus::None, tr("Plan a valid path first")};
}

}  // namespace demoplan::ui
