#pragma once
// Time parameterization of a planned path (docs/trajectory.md): the robot rests at the first
// and last waypoint and at every grasp or release; it passes through the other waypoints
// without stopping. Between waypoints it follows the straight joint-space segment with a
// time-optimal jerk-limited profile; at a pass-through waypoint the segment's last and the
// next segment's first `blend_length` are replaced by two quintic pieces that pass exactly
// through the waypoint, each joint moving monotonically (never beyond the neighbouring
// waypoints' values). Velocities, accelerations and jerks stay within the limits everywhere.
#include <string>
#include <vector>

#include "core/path/path.h"
#include "core/trajectory/joint_limits.h"
#include "core/trajectory/trajectory.h"

namespace demoplan {

struct TimingOptions {
  // Joint-space length (rad, m) of each side of the blend at a pass-through waypoint, capped at a
  // third of the segment. Longer blends pass faster and stray further from the straight segments.
  double blend_length = 0.1;
  // Plan within this fraction of every limit (the blend pieces are sized from samples).
  double limit_margin = 0.995;
  std::string source = "path";  // names the path in errors
  // Waypoints where the robot must rest although it could pass (e.g. a blend there grazes an
  // obstacle); indices into the path's waypoints.
  std::vector<size_t> rest_at;
};

// Throws InputError (via check_path_within_limits) for a path outside the limits.
Trajectory time_parameterize(const Path& path, const JointLimitSet& limits, const TimingOptions& options = {});

}  // namespace demoplan
