#include "core/placement/placement_candidate.h"

#include <algorithm>

namespace demoplan {

namespace {

const PlacementRun* best_run(const std::vector<PlacementRun>& runs) {
  const PlacementRun* best = nullptr;
  for (const PlacementRun& r : runs)
    if (r.valid && (!best || r.cycle_time_s < best->cycle_time_s)) best = &r;
  return best;
}

}  // namespace

double PlacementCandidate::success_rate() const {
  if (runs.empty()) return 0;
  return static_cast<double>(std::count_if(runs.begin(), runs.end(), [](const auto& r) { return r.valid; })) /
         static_cast<double>(runs.size());
}

double PlacementCandidate::median_time_s() const {
  if (runs.empty()) return 0;
  std::vector<double> t;
  for (const auto& r : runs) t.push_back(r.planning_time_s);
  std::sort(t.begin(), t.end());
  const size_t n = t.size();
  return n % 2 ? t[n / 2] : (t[n / 2 - 1] + t[n / 2]) / 2;
}

std::optional<double> PlacementCandidate::cycle_time_s() const {
  const PlacementRun* best = best_run(runs);
  return best ? std::optional<double>(best->cycle_time_s) : std::nullopt;
}

std::optional<double> PlacementCandidate::path_length() const {
  const PlacementRun* best = best_run(runs);
  return best ? std::optional<double>(best->path_length) : std::nullopt;
}

bool ranks_before(const PlacementCandidate& a, const PlacementCandidate& b) {
  constexpr double kNone = 1e300;
  // A base that does not fit is never better, whatever the planner (which does not check the
  // base against the furniture, as the benchmark does not) made of it with --plan-rejected.
  if (a.feasible != b.feasible) return a.feasible;
  const double sa = a.success_rate(), sb = b.success_rate();
  if (sa != sb) return sa > sb;
  const double ca = a.cycle_time_s().value_or(kNone), cb = b.cycle_time_s().value_or(kNone);
  if (ca != cb) return ca < cb;
  return a.index < b.index;
}

void rank_candidates(std::vector<PlacementCandidate>& candidates) {
  std::sort(candidates.begin(), candidates.end(), ranks_before);
}

}  // namespace demoplan
