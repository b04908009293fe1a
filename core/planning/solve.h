#pragma once
// The whole planning job as the CLI and the GUI run it: the guided planner, then shortcutting,
// then the independent validator as a final gate. A shortened path the validator rejects (a
// long straight cut can graze an obstacle between collision-check samples) is dropped for the
// planner's own path, which is validated in turn.
#include "core/planning/planner.h"
#include "core/planning/shortcut.h"
#include "core/validation/path_validator.h"

namespace demoplan {

struct SolveParams {
  PlannerParams planner;
  bool shortcut = true;
  ShortcutParams shortcutting;
};

struct SolveResult {
  PlanResult plan;                 // plan.path: the path returned (shortened when it validated)
  bool shortened = false;
  ShortcutResult shortcut;
  ValidationReport validation;     // of the returned path
  std::string shortcut_rejection;  // why a shortened path was dropped, if it was
};

SolveResult solve(const Scene& scene, const ConstraintGraph& graph, const CollisionChecker& checker,
                  const ValidationTask& task, const SolveParams& params, const ProgressCallback& progress = {},
                  const std::atomic<bool>* cancel = nullptr);

}  // namespace demoplan
