#include "core/planning/plan_job.h"

#include <chrono>

#include "core/planning/planner_registry.h"

namespace demoplan {

PlanReport run_plan_job(const PlanningProblem& problem, const PlannerSettings& settings,
                        const ProgressCallback& progress, const std::atomic<bool>* cancel,
                        const PlanJobOptions& options) {
  const auto t0 = std::chrono::steady_clock::now();
  const std::unique_ptr<Planner> planner = make_planner(settings);
  PlanReport r;
  r.planner = planner->name();
  r.plan = planner->solve(problem, StopCondition(settings.planner.time_limit, cancel), progress);
  const bool cancelled = r.plan.cancelled || (cancel && cancel->load());
  if (r.plan.solved) {
    if (options.validate_planner_path)
      r.planner_validation = validate_path(*problem.scene, problem.validation, r.plan.path);
    r.path = r.plan.path;
    if (settings.shortcut && settings.shortcutting.time_limit > 0 && !cancelled) {
      Path shorter = r.plan.path;
      ShortcutParams sp = settings.shortcutting;
      sp.seed = settings.planner.seed;
      // The path of a planner that made its own graph (unguided, a guided regrasp) lies in its states.
      const ConstraintGraph& graph = r.plan.graph ? *r.plan.graph : *problem.graph;
      r.shortcut = shortcut_path(*problem.scene, graph, *problem.checker, shorter, sp);
      ValidationReport v = validate_path(*problem.scene, problem.validation, shorter);
      if (v.valid) {
        r.path = std::move(shorter);
        r.validation = std::move(v);
        r.shortened = true;
      } else {
        r.shortcut_rejection = v.message;
      }
    }
    if (!r.shortened) {
      if (!options.validate_planner_path)
        r.planner_validation = validate_path(*problem.scene, problem.validation, r.plan.path);
      r.validation = r.planner_validation;
    }
  } else if (!cancelled && options.assess_on_failure) {
    r.feasibility = assess_problem(problem, settings);
  }
  r.wall_time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return r;
}

FeasibilityReport assess_problem(const PlanningProblem& problem, const PlannerSettings& settings) {
  return assess_picks(*problem.scene, *problem.graph, *problem.checker, settings.feasibility_samples,
                      settings.planner.seed);
}

}  // namespace demoplan
