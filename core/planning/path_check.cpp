#include "core/planning/path_check.h"

#include "core/path/path_interpolation.h"

namespace demoplan {

int first_colliding_segment(const Scene& scene, const CollisionChecker& checker, CollisionData& data,
                            const Path& path, double delta, double max_step,
                            const std::function<bool()>& keep_going) {
  const PathInterpolator interp(scene, path);
  const std::vector<double> ts = interp.sample_parameters(delta, max_step);
  long count = 0;
  for (const double t : ts) {
    if (++count % 64 == 0 && !keep_going()) return -1;
    if (!checker.in_collision(interp.at(t), data)) continue;
    int k = 0;
    while (k + 2 < static_cast<int>(path.waypoints.size()) && interp.waypoint_parameter(static_cast<size_t>(k) + 1) <= t) ++k;
    return k;
  }
  return -1;
}

}  // namespace demoplan
