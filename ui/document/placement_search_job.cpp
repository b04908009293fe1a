#include "ui/document/placement_search_job.h"

#include "core/error.h"
#include "core/placement/placement_search.h"
#include "core/project/placement_problem.h"
#include "ui/document/document.h"

namespace demoplan::ui {

PlacementSearchJob::PlacementSearchJob(Document* doc) : BackgroundJob(doc), doc_(doc) {
  connect(doc, &Document::projectLoaded, this, [this] {
    cancel();
    settings_.reset();
    clear();
  });
}

PlacementSearchSettings PlacementSearchJob::settings() const {
  if (settings_) return *settings_;
  PlacementSearchSettings s;
  Eigen::Vector3d base = Eigen::Vector3d::Zero();
  if (doc_->hasProject()) base = doc_->scene().robot.base.translation();
  s.region = {{base.x() - 0.6, base.x() + 0.6}, {base.y() - 0.6, base.y() + 0.6}, {-M_PI, M_PI}, std::nullopt};
  return s;
}

void PlacementSearchJob::setSettings(const PlacementSearchSettings& settings) { settings_ = settings; }

const PlacementCandidate* PlacementSearchJob::best() const {
  const PlacementCandidate* best = nullptr;
  for (const auto& c : candidates_)
    if (c.usable() && (!best || ranks_before(c, *best))) best = &c;
  return best;
}

void PlacementSearchJob::clear() {
  candidates_.clear();
  total_ = 0;
  emit cleared();
}

bool PlacementSearchJob::start(QString* error) {
  auto fail = [&](const QString& why) {
    if (error) *error = why;
    return false;
  };
  if (isRunning()) return fail(tr("A search is running."));
  if (!doc_->hasProject()) return fail(tr("No project is open."));
  if (!doc_->issues().empty()) return fail(tr("The demonstration has issues: fix them on the timeline first."));
  const PlacementSearchSettings s = settings();
  ProblemAtBase problem_at;
  try {
    std::optional<BenchmarkRobot> robot;
    if (!doc_->cell()) robot = load_benchmark_robot(doc_->task()->data_dir, doc_->sceneReference().robot);
    problem_at = problem_at_base(doc_->sharedScene(), std::make_shared<const Demonstration>(doc_->demonstration()), robot);
  } catch (const InputError& e) {
    return fail(QString::fromStdString(e.what()));
  }
  const std::vector<BasePose> poses =
      candidate_base_poses(s.region, s.samples, doc_->scene().robot.base.translation().z());
  std::vector<int> indices(poses.size());
  for (size_t i = 0; i < indices.size(); ++i) indices[i] = static_cast<int>(i);
  PlacementSettings placement;
  placement.planner = doc_->planning()->settings();
  placement.planner.planner.time_limit = s.time_limit_s;
  placement.seeds.clear();
  for (int seed = 1; seed <= s.seeds; ++seed) placement.seeds.push_back(static_cast<std::uint64_t>(seed));
  candidates_.clear();
  total_ = static_cast<int>(poses.size());
  emit cleared();
  return run([this, problem_at, poses, indices, placement, jobs = s.jobs](const Post& post, const std::atomic<bool>& cancel) {
    run_placement_search(
        problem_at, poses, indices, placement, jobs,
        [&](const PlacementCandidate& c, size_t done, size_t total) {
          post([this, c, done, total] {
            candidates_.push_back(c);
            emit candidateDone(static_cast<int>(done), static_cast<int>(total));
          });
        },
        &cancel);
    post([this] {
      finish();
      emit finished();
    });
  });
}

}  // namespace demoplan::ui
