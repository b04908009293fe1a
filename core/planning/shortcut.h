#pragma once
// Random shortcutting (Sec. III-D): pick two configurations on the path that lie in the same
// state, with no state change and no approach move between them; if the straight segment
// joining them is collision-free in that state, it replaces the portion between them.
#include <cstdint>

#include "core/graph/constraint_graph.h"
#include "core/path/path.h"
#include "core/scene/collision_checker.h"

namespace demoplan {

struct ShortcutParams {
  double time_limit = 1.0;   // s
  long max_attempts = 100000;
  // Stop after this many attempts in a row shortened nothing: the path has converged, and the
  // rest of time_limit would be spent on cuts that fail.
  long max_failures = 200;
  // Collision-check step (joint space, rad): finer than the planner's, because a long cut can
  // run close along an obstacle.
  double resolution = 0.0025;
  std::uint64_t seed = 1;
  // Beyond the paper: before shortcutting, a detour that grasps a part and puts it back
  // unmoved is replaced by a link within the placement state (RRT-Connect), trying for up to
  // this long (s) and at most detour_rounds rounds of RRT-Connect per detour; time_limit then
  // applies to the shortcuts.
  double detour_time = 1.0;
  long detour_rounds = 1000;
};

struct ShortcutResult {
  double length_before = 0.0, length_after = 0.0;  // robot joint-space length (rad)
  long attempts = 0, accepted = 0;
  int detours_removed = 0;  // grasps of a part that was put back unmoved, cut out
  double time_s = 0.0;
};

// Shortens `path` in place; it stays a path of the same states in the same order, less any
// detour that leaves a placement state and returns to it.
ShortcutResult shortcut_path(const Scene& scene, const ConstraintGraph& graph, const CollisionChecker& checker,
                             Path& path, const ShortcutParams& params);

}  // namespace demoplan
