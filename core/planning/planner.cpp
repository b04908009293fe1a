#include "core/planning/planner.h"

namespace demoplan {

bool stop_requested(const StopCondition& stop, long iterations, long max_iterations, PlanResult& r) {
  if (stop.cancelled()) {
    r.cancelled = true;
    r.message = "cancelled after " + std::to_string(iterations) + " iterations";
    return true;
  }
  if (iterations >= max_iterations) {
    r.message = "iteration limit (" + std::to_string(max_iterations) + ") reached";
    return true;
  }
  if (stop.timed_out()) {
    r.message = "time limit (" + std::to_string(stop.time_limit_s()) + " s) reached";
    return true;
  }
  return false;
}

}  // namespace demoplan
