#include "core/geometry/polygon_2d.h"

#include <algorithm>

namespace demoplan {

bool contains_from_above(const std::vector<Eigen::Vector3d>& polygon, const Eigen::Vector3d& point) {
  for (size_t i = 0; i < polygon.size(); ++i) {
    const Eigen::Vector3d& a = polygon[i];
    const Eigen::Vector3d& b = polygon[(i + 1) % polygon.size()];
    if (cross2((b - a).head<2>(), (point - a).head<2>()) < 0) return false;
  }
  return polygon.size() >= 3;
}

double polygon_area(const std::vector<Eigen::Vector2d>& p) {
  double a = 0.0;
  for (size_t i = 0; i < p.size(); ++i) a += cross2(p[i], p[(i + 1) % p.size()]);
  return 0.5 * a;
}

std::vector<int> hull_2d(const std::vector<Eigen::Vector2d>& p) {
  std::vector<int> idx(p.size());
  for (size_t i = 0; i < p.size(); ++i) idx[i] = static_cast<int>(i);
  std::sort(idx.begin(), idx.end(), [&](int a, int b) { return p[a].x() < p[b].x() || (p[a].x() == p[b].x() && p[a].y() < p[b].y()); });
  std::vector<int> h(2 * idx.size() + 1);
  size_t k = 0;
  for (int pass = 0; pass < 2; ++pass) {
    const size_t start = k;
    for (size_t j = 0; j < idx.size(); ++j) {
      const int i = pass == 0 ? idx[j] : idx[idx.size() - 1 - j];
      while (k >= start + 2 && cross2(p[h[k - 1]] - p[h[k - 2]], p[i] - p[h[k - 2]]) <= 0) --k;
      h[k++] = i;
    }
    --k;  // the last point is the first of the other chain
  }
  h.resize(k);
  return h;
}


}  // namespace demoplan
