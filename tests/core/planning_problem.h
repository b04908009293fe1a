#pragma once
// A benchmark instance ready to plan and validate: the task, its scene for one robot and base
// pose, the constraint graph of its cleaned demonstration, a collision checker, and what the
// validator checks a path against. Shared by the planner and shortcut tests.
#include <memory>
#include <string>

#include "core/demo/benchmark_demonstration.h"
#include "core/demo/benchmark_scene.h"
#include "core/graph/constraint_graph.h"
#include "core/scene/collision_checker.h"
#include "core/validation/path_validator.h"

namespace demoplan {

struct PlanningProblem {
  BenchmarkTask task;
  Scene scene;
  ConstraintGraph graph;
  std::unique_ptr<CollisionChecker> checker;
  ValidationTask vtask;

  PlanningProblem(const std::string& name, const std::string& robot, int pose)
      : task(load_benchmark_task(DEMOPLAN_DATA_DIR, name)), scene(build_benchmark_scene(task, robot, pose)) {
    graph = build_constraint_graph(scene, demonstration_from_benchmark(task, scene, PoseSource::Subgoals));
    checker = std::make_unique<CollisionChecker>(scene);
    vtask = validation_task(task, scene);
  }
};

}  // namespace demoplan
