#include "core/geometry/ray_box.h"

#include <algorithm>
#include <cmath>

namespace demoplan {

bool ray_hits_box(const Eigen::Vector3d& o, const Eigen::Vector3d& d, const Eigen::AlignedBox3d& box, double t_min,
                  double t_max) {
  for (int i = 0; i < 3; ++i) {
    if (std::abs(d[i]) < 1e-12) {  // parallel to this slab: inside it or never
      if (o[i] < box.min()[i] || o[i] > box.max()[i]) return false;
      continue;
    }
    double a = (box.min()[i] - o[i]) / d[i], b = (box.max()[i] - o[i]) / d[i];
    if (a > b) std::swap(a, b);
    t_min = std::max(t_min, a);
    t_max = std::min(t_max, b);
    if (t_min > t_max) return false;
  }
  return true;
}

}  // namespace demoplan
