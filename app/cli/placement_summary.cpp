#include "app/cli/placement_summary.h"

#include <cmath>
#include <cstdio>
#include <iostream>

namespace demoplan::cli {

void print_placement_summary(const PlacementResult& r, int rows) {
  int planned = 0;
  for (const auto& c : r.candidates) planned += !c.runs.empty();
  std::cerr << r.candidates.size() << " of " << r.candidate_count << " candidates"
            << (r.complete() ? "" : " (shard " + std::to_string(r.shard) + "/" + std::to_string(r.shards) + ")")
            << ": " << r.feasible_count() << " pass the screen, " << planned << " planned, in "
            << std::lround(r.wall_time_s * 10) / 10.0 << " s" << (r.cancelled ? " (cancelled)" : "") << "\n";
  if (!r.complete()) return;
  if (!r.message().empty()) std::cerr << r.message() << "\n";
  else std::cerr << " rank  index      x      y      z   yaw(deg)  success  cycle(s)  plan(s)\n";
  for (int k = 0; k < rows && k < static_cast<int>(r.candidates.size()); ++k) {
    const PlacementCandidate& c = r.candidates[static_cast<size_t>(k)];
    if (!c.usable()) break;
    char line[160];
    std::snprintf(line, sizeof line, "%5d %6d %6.3f %6.3f %6.3f %9.1f %8.2f %9.2f %8.2f\n", k + 1, c.index, c.base.x,
                  c.base.y, c.base.z, c.base.yaw * 180 / M_PI, c.success_rate(), c.cycle_time_s().value_or(NAN),
                  c.median_time_s());
    std::cerr << line;
  }
  for (const PlacementCandidate& c : r.published) {
    char line[160];
    if (c.usable())
      std::snprintf(line, sizeof line, "published pose %d: %.0f %% valid, cycle %.2f s\n", c.index,
                    c.success_rate() * 100, *c.cycle_time_s());
    else
      std::snprintf(line, sizeof line, "published pose %d: %s\n", c.index,
                    c.feasible ? "no valid plan" : ("rejected: " + c.reason.substr(0, 100)).c_str());
    std::cerr << line;
  }
}

nlohmann::json placement_summary_json(const PlacementResult& r, const std::string& out) {
  nlohmann::json j = placement_result_json(r);
  j["out"] = out;
  return j;
}

}  // namespace demoplan::cli
