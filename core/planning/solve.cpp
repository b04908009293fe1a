#include "core/planning/solve.h"

namespace demoplan {

SolveResult solve(const Scene& scene, const ConstraintGraph& graph, const CollisionChecker& checker,
                  const ValidationTask& task, const SolveParams& params, const ProgressCallback& progress,
                  const std::atomic<bool>* cancel) {
  SolveResult r;
  r.plan = plan_guided(scene, graph, checker, params.planner, progress, cancel);
  if (!r.plan.solved) return r;
  if (params.shortcut && !(cancel && cancel->load())) {
    Path shorter = r.plan.path;
    ShortcutParams sp = params.shortcutting;
    sp.seed = params.planner.seed;
    r.shortcut = shortcut_path(scene, graph, checker, shorter, sp);
    ValidationReport v = validate_path(scene, task, shorter);
    if (v.valid) {
      r.plan.path = std::move(shorter);
      r.validation = std::move(v);
      r.shortened = true;
      return r;
    }
    r.shortcut_rejection = v.message;
  }
  r.validation = validate_path(scene, task, r.plan.path);
  return r;
}

}  // namespace demoplan
