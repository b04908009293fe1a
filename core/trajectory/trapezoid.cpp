#include "core/trajectory/trapezoid.h"

#include <cmath>
#include <limits>

namespace demoplan {

double trapezoid_duration(const Path& path, const JointLimitSet& limits) {
  double total = 0;
  for (size_t k = 1; k < path.waypoints.size(); ++k) {
    const Eigen::VectorXd d = path.waypoints[k].q - path.waypoints[k - 1].q;
    const double length = d.norm();
    if (length <= 0) continue;
    // Along the straight segment, the joint with the least room sets the limits.
    double v = std::numeric_limits<double>::infinity(), a = v;
    for (long j = 0; j < d.size(); ++j) {
      const double u = std::abs(d[j]) / length;
      if (u == 0) continue;
      v = std::min(v, limits.velocity[j] / u);
      a = std::min(a, limits.acceleration[j] / u);
    }
    total += length >= v * v / a ? length / v + v / a : 2 * std::sqrt(length / a);
  }
  return total;
}

}  // namespace demoplan
