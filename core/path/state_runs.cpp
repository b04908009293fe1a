#include "core/path/state_runs.h"

namespace demoplan {

std::vector<StateRun> state_runs(const Path& path) {
  const auto& w = path.waypoints;
  std::vector<StateRun> out;
  // A segment k -> k+1 is a free move when both ends share a state and it is not an approach.
  auto free_move = [&](size_t k) { return !w[k].approach && w[k].state == w[k + 1].state; };
  for (size_t k = 0; k + 1 < w.size();) {
    if (!free_move(k)) {
      ++k;
      continue;
    }
    size_t end = k + 1;
    while (end + 1 < w.size() && free_move(end)) ++end;
    if ((w[end].q - w[k].q).norm() > 1e-9) out.push_back({w[k].state, k, end});
    k = end;
  }
  return out;
}

}  // namespace demoplan
