#pragma once
// The single-state motions of a path: each maximal run of consecutive waypoints that stay in one
// constraint-graph state and are joined by free moves (not a transition's straight approach or
// retreat). These are the transit and transfer pieces a planner inside one state must find,
// e.g. to compare single-state planners on the motions a guided solution needed.
#include <vector>

#include "core/path/path.h"

namespace demoplan {

struct StateRun {
  int state = -1;
  size_t first = 0, last = 0;  // waypoint indices, first < last
};

// In path order. A run moves between two distinct configurations (a run whose ends coincide
// within 1e-9 asks nothing of a planner and is left out).
std::vector<StateRun> state_runs(const Path& path);

}  // namespace demoplan
