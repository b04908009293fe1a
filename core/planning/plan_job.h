#pragma once
// The whole planning job, as `demoplan-cli plan`, `demoplan-cli bench` and the GUI's planner
// run it: the chosen planner until solved or stopped, shortcutting, the independent validator
// as the final gate, and after a failure the reason (can every pick be done from this base
// pose at all?). A shortened path the validator rejects (a long straight cut can graze an
// obstacle between collision-check samples) is dropped for the planner's own path.
#include <atomic>
#include <optional>
#include <string>

#include "core/graph/pick_feasibility.h"
#include "core/planning/planner_settings.h"
#include "core/planning/planning_problem.h"

namespace demoplan {

struct PlanReport {
  std::string planner;  // the registered name
  PlanResult plan;      // the planner's own result; plan.path is its path, unshortened
  ValidationReport planner_validation;  // of plan.path, when solved (see PlanJobOptions)
  Path path;            // the path returned: the shortened one when it validated, else plan.path
  bool shortened = false;
  ShortcutResult shortcut;
  std::string shortcut_rejection;  // why a shortened path was dropped, if it was
  ValidationReport validation;     // of `path`
  // After a failure that was not a cancel (when asked for): which picks cannot be done.
  std::optional<FeasibilityReport> feasibility;
  double wall_time_s = 0.0;  // the whole job

  bool solved() const { return plan.solved; }
  bool valid() const { return plan.solved && validation.valid; }
};

struct PlanJobOptions {
  bool assess_on_failure = true;  // false: the caller assesses (bench does it once per instance)
  // false: the planner's own path is validated only when it is the one returned (a shortened
  // path was dropped or not made); `plan` reports only the returned path.
  bool validate_planner_path = true;
};

// Runs the planner settings.planner_name with a StopCondition of settings.planner.time_limit
// and `cancel`. Throws InputError for an unknown planner.
PlanReport run_plan_job(const PlanningProblem& problem, const PlannerSettings& settings,
                        const ProgressCallback& progress = {}, const std::atomic<bool>* cancel = nullptr,
                        const PlanJobOptions& options = {});

// Whether each pick of the problem's demonstration can be done at all, sampled as the plan job
// does after a failure.
FeasibilityReport assess_problem(const PlanningProblem& problem, const PlannerSettings& settings);

}  // namespace demoplan
