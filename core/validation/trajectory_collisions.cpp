#include "core/validation/trajectory_collisions.h"

#include <algorithm>
#include <cmath>

#include "core/path/path_interpolation.h"

namespace demoplan {

TrajectoryCollision first_trajectory_collision(const Scene& scene, const CollisionChecker& checker, const Path& path,
                                               const Trajectory& tr, double resolution) {
  const PathInterpolator along(scene, path);
  CollisionData data = checker.make_data();
  TrajectoryCollision result;
  for (const Trajectory::Blend& b : tr.blends) {
    // A time step that keeps consecutive samples within the resolution, from the blend's peak
    // joint-space speed (sampled densely, with a margin for the speed between samples).
    double peak = 0;
    for (int i = 0; i <= 32; ++i) peak = std::max(peak, tr.sample_at(b.begin + (b.end - b.begin) * i / 32).v.norm());
    const int steps = std::max(1, static_cast<int>(std::ceil(2 * peak * (b.end - b.begin) / resolution)));
    const size_t w = b.waypoint;
    for (int i = 0; i <= steps; ++i) {
      const double t = b.begin + (b.end - b.begin) * i / steps;
      const Eigen::VectorXd q = tr.sample_at(t).q;
      // Before the waypoint the robot is on segment w-1 (u near 1), after it on segment w.
      const SceneState state = t <= tr.waypoint_times[w] ? along.on_segment(w - 1, q, 1.0) : along.on_segment(w, q, 0.0);
      CollisionPair hit;
      if (!checker.in_collision(state, data, {}, &hit)) continue;
      result.free = false;
      result.time = t;
      result.waypoint = w;
      result.pair = hit;
      return result;
    }
  }
  return result;
}

ClearTrajectory time_parameterize_clear(const Scene& scene, const CollisionChecker& checker, const Path& path,
                                        const JointLimitSet& limits, TimingOptions options) {
  ClearTrajectory r;
  for (;;) {
    r.trajectory = time_parameterize(path, limits, options);
    const TrajectoryCollision c = first_trajectory_collision(scene, checker, path, r.trajectory);
    if (c.free) return r;
    options.rest_at.push_back(c.waypoint);  // that blend is gone next time: this terminates
    r.rests_added.push_back(c.waypoint);
  }
}

}  // namespace demoplan
