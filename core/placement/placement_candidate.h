#pragma once
// One candidate base pose of the placement search as judged: the screen's verdict and one
// planning run per seed, and the order candidates rank in. Plain data with its summaries, apart
// from the search that fills it (base_placement.h), so that the result file's reader
// (placement_result.h) stands without the planner.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "core/placement/placement_region.h"

namespace demoplan {

struct PlacementRun {
  std::uint64_t seed = 0;
  bool valid = false;  // solved and accepted by the validator
  double planning_time_s = 0;
  double cycle_time_s = 0;  // trajectory duration, when valid
  double path_length = 0;   // robot joint-space length (rad, m), when valid
  int grasps = 0;
  std::string message;  // why not valid
};

struct PlacementCandidate {
  int index = -1;  // in the search's candidate list
  BasePose base;
  bool screened = false;  // the screen ran (false: cancelled before)
  bool feasible = false;  // the screen passed
  std::string reason;     // the screen's: the first thing that cannot be done, and why
  double screen_time_s = 0;
  std::vector<PlacementRun> runs;  // one per seed, when feasible (or when planning was forced)

  double success_rate() const;  // valid runs / runs; 0 without runs
  // The robot can stand here and do the task: it passed the screen and a plan was found.
  bool usable() const { return feasible && success_rate() > 0; }
  double median_time_s() const; // planning time over all runs; 0 without runs
  // The shortest cycle time of a valid run: the program one would export.
  std::optional<double> cycle_time_s() const;
  std::optional<double> path_length() const;  // of that run
};

// Best first: those that pass the screen, then the highest success rate, then the shortest cycle
// time, then the index (so equal candidates keep one order whichever machine or shard evaluated
// them).
void rank_candidates(std::vector<PlacementCandidate>& candidates);
// The order rank_candidates sorts by: true when `a` goes before `b`.
bool ranks_before(const PlacementCandidate& a, const PlacementCandidate& b);

}  // namespace demoplan
