#pragma once
// Runs core's plan job (core/planning/plan_job.h: the planning problem's constraint graph, the
// planner, shortcut, validator, and the reason after a failure) on a background thread and
// reports to the GUI thread: the graph when it is built, progress snapshots with the trees' new
// edges as gripper positions, and the outcome.
//
// Cancel answers at once: the runner drops the job (its late result is ignored) and is idle
// again; the planner sees the flag within a few ms, the shortcut/validator phases finish on
// their own thread in the background.
#include <QObject>
#include <QVector3D>
#include <atomic>
#include <memory>
#include <thread>
#include <vector>

#include "core/graph/constraint_graph.h"
#include "core/planning/plan_job.h"

namespace demoplan::ui {

struct PlanJob {
  std::shared_ptr<const Scene> scene;
  Demonstration demonstration;  // settled onto its supports before planning (settle_for_planning)
  std::string demonstration_source = "demonstration";  // names it in errors
  PlannerSettings settings;
  std::string task, robot;
  int robot_pose = 0;
};

// One edge of a tree, as the two gripper positions it joins (world, metres).
struct TreeEdge {
  int tree = -1;
  int state = -1;
  QVector3D from, to;
};
struct TreeRoot {
  int state = -1;
  QVector3D position;
};

struct PlanSnapshot {
  double elapsed_s = 0.0;
  long iterations = 0;
  int trees = 0;
  size_t nodes = 0;
  std::vector<size_t> state_nodes;
  std::vector<std::string> state_names;  // a planner's own states (unguided); empty: the graph's
  std::vector<TreeEdge> new_edges;
  std::vector<TreeRoot> new_roots;
  bool final = false;
};

struct PlanOutcome {
  std::string error;  // the demonstration cannot be planned (graph construction failed)
  std::shared_ptr<const ConstraintGraph> graph;  // null when it could not be built
  std::string validated_against;                 // the validation task's source
  PlanReport report;  // report.path carries task, robot and pose
};

class PlanRunner : public QObject {
  Q_OBJECT
public:
  explicit PlanRunner(QObject* parent = nullptr);
  ~PlanRunner() override;  // cancels and joins every job still running

  // False when a job is already running.
  bool start(PlanJob job);
  // Drops the running job: emits cancelled() before returning.
  void cancel();
  bool isRunning() const { return running_; }
  // The last snapshot of the running (or last) job.
  const PlanSnapshot& lastSnapshot() const { return last_; }

signals:
  void started();
  void graphReady(std::shared_ptr<const ConstraintGraph> graph);
  void progress(const PlanSnapshot& snapshot);
  void finished(const PlanOutcome& outcome);
  void cancelled(const PlanSnapshot& last);

private:
  struct Worker {
    std::thread thread;
    std::shared_ptr<std::atomic<bool>> cancel;
    std::shared_ptr<std::atomic<bool>> done;
  };
  void reapFinishedWorkers();

  bool running_ = false;
  int generation_ = 0;
  PlanSnapshot last_;
  std::vector<Worker> workers_;
};

}  // namespace demoplan::ui
