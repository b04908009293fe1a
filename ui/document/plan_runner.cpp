#include "ui/document/plan_runner.h"

#include <QMetaObject>
#include <QPointer>
#include <chrono>

#include "core/demo/supported_rests.h"
#include "core/error.h"

namespace demoplan::ui {

namespace {
QVector3D to_qt(const Eigen::Vector3d& p) { return QVector3D(float(p.x()), float(p.y()), float(p.z())); }
}  // namespace

PlanRunner::PlanRunner(QObject* parent) : QObject(parent) {}

PlanRunner::~PlanRunner() {
  for (auto& w : workers_) {
    w.cancel->store(true);
    if (w.thread.joinable()) w.thread.join();
  }
}

void PlanRunner::reapFinishedWorkers() {
  for (auto it = workers_.begin(); it != workers_.end();) {
    if (it->done->load()) {
      if (it->thread.joinable()) it->thread.join();
      it = workers_.erase(it);
    } else {
      ++it;
    }
  }
}

bool PlanRunner::start(PlanJob job) {
  if (running_) return false;
  reapFinishedWorkers();
  running_ = true;
  last_ = PlanSnapshot{};
  const int generation = ++generation_;
  auto cancel = std::make_shared<std::atomic<bool>>(false);
  auto done = std::make_shared<std::atomic<bool>>(false);
  QPointer<PlanRunner> self(this);
  emit started();

  auto work = [self, generation, cancel, done, job = std::move(job)]() mutable {
    // Delivers `f` on the GUI thread, unless the runner is gone or the job was dropped.
    auto post = [&](auto f) {
      if (cancel->load()) return;
      PlanRunner* runner = self.data();
      if (!runner) return;
      QMetaObject::invokeMethod(
          runner,
          [self, generation, f = std::move(f)]() mutable {
            if (self && self->generation_ == generation && self->running_) f(*self);
          },
          Qt::QueuedConnection);
    };
    auto outcome = std::make_shared<PlanOutcome>();
    try {
      const Scene& scene = *job.scene;
      // A part resting on no support is refused here, naming the event, not after minutes of planning.
      const Demonstration demo = settle_for_planning(scene, job.demonstration, job.demonstration_source);
      const PlanningProblem problem = make_planning_problem(job.scene, demo, validation_task(demo, scene));
      outcome->graph = problem.graph;
      outcome->validated_against = problem.validation.source;
      post([graph = problem.graph](PlanRunner& r) { emit r.graphReady(graph); });
      auto on_progress = [&](const PlannerProgress& p) {
        auto snap = std::make_shared<PlanSnapshot>();
        snap->elapsed_s = p.elapsed_s;
        snap->iterations = p.iterations;
        snap->trees = p.trees;
        snap->nodes = p.nodes;
        snap->state_nodes = p.state_nodes;
        snap->state_names = p.state_names;
        snap->final = p.final;
        snap->new_edges.reserve(p.new_edges.size());
        for (const EdgeSnapshot& e : p.new_edges)
          snap->new_edges.push_back({e.tree, e.state, to_qt(gripper_pose(scene, e.from).translation()),
                                     to_qt(gripper_pose(scene, e.to).translation())});
        for (const auto& [state, q] : p.new_roots)
          snap->new_roots.push_back({state, to_qt(gripper_pose(scene, q).translation())});
        post([snap](PlanRunner& r) {
          r.last_ = *snap;
          emit r.progress(r.last_);
        });
      };
      outcome->report = run_plan_job(problem, job.settings, on_progress, cancel.get());
      Path& path = outcome->report.path;
      path.task = job.task;
      path.robot = job.robot;
      path.robot_pose = job.robot_pose;
    } catch (const std::exception& e) {
      outcome->error = e.what();
    }
    post([outcome](PlanRunner& r) {
      r.running_ = false;
      emit r.finished(*outcome);
    });
    done->store(true);
  };
  workers_.push_back({std::thread(std::move(work)), cancel, done});
  return true;
}

void PlanRunner::cancel() {
  if (!running_) return;
  for (auto& w : workers_) w.cancel->store(true);
  running_ = false;
  ++generation_;
  emit cancelled(last_);
}

}  // namespace demoplan::ui
