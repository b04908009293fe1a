#pragma once
// A benchmark instance ready to plan and validate: the task, and core's PlanningProblem for one
// robot and base pose of its cleaned demonstration (deck placement done), with shorthands for
// its parts. Shared by the planner and shortcut tests.
#include <memory>
#include <string>

#include "core/demo/benchmark_scene.h"
#include "core/project/benchmark_instance.h"
#include "core/planning/guided_planner.h"

namespace demoplan {

struct BenchmarkProblem {
  BenchmarkTask task;
  PlanningProblem problem;
  const Scene& scene;
  const ConstraintGraph& graph;
  const CollisionChecker* checker;
  const ValidationTask& vtask;

  BenchmarkProblem(const std::string& name, const std::string& robot, int pose,
                   const std::string& data_dir = DEMOPLAN_DATA_DIR)
      : task(load_benchmark_task(data_dir, name)), problem(make(task, robot, pose)), scene(*problem.scene),
        graph(*problem.graph), checker(problem.checker.get()), vtask(problem.validation) {}

  // The guided planner with params.time_limit (and `cancel`) as its stop condition.
  PlanResult plan(const PlannerParams& params, const ProgressCallback& progress = {},
                  const std::atomic<bool>* cancel = nullptr) const {
    return GuidedPlanner(params).solve(problem, StopCondition(params.time_limit, cancel), progress);
  }

private:
  static PlanningProblem make(const BenchmarkTask& task, const std::string& robot, int pose) {
    return make_benchmark_instance(task, std::make_shared<const Scene>(build_benchmark_scene(task, robot, pose)),
                                   PoseSource::Subgoals).problem;
  }
};

}  // namespace demoplan
