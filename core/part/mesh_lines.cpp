#include "core/part/mesh_lines.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

namespace demoplan {

MeshLines::MeshLines(const std::vector<Eigen::Vector3d>& vertices,
                     const std::vector<std::array<std::uint32_t, 3>>& triangles, const Eigen::Vector3d& direction,
                     int cells)
    : d_(direction.normalized()), triangles_(triangles) {
  // Any basis of the plane normal to the direction.
  const Eigen::Vector3d helper = std::abs(d_.x()) < 0.9 ? Eigen::Vector3d::UnitX() : Eigen::Vector3d::UnitY();
  u_ = d_.cross(helper).normalized();
  v_ = d_.cross(u_);
  local_.reserve(vertices.size());
  Eigen::Vector2d lo = Eigen::Vector2d::Constant(1e300), hi = Eigen::Vector2d::Constant(-1e300);
  for (const auto& p : vertices) {
    local_.emplace_back(p.dot(u_), p.dot(v_), p.dot(d_));
    lo = lo.cwiseMin(local_.back().head<2>());
    hi = hi.cwiseMax(local_.back().head<2>());
  }
  normals_.reserve(triangles.size());
  for (const auto& t : triangles) {
    const Eigen::Vector3d n = (vertices[t[1]] - vertices[t[0]]).cross(vertices[t[2]] - vertices[t[0]]);
    const double len = n.norm();
    normals_.push_back(len > 0 ? Eigen::Vector3d(n / len) : Eigen::Vector3d::Zero());
  }
  if (vertices.empty()) return;
  lo_ = lo;
  const Eigen::Vector2d size = (hi - lo).cwiseMax(1e-9);
  cell_ = size.maxCoeff() / std::max(1, cells);
  nx_ = std::max(1, static_cast<int>(std::ceil(size.x() / cell_)));
  ny_ = std::max(1, static_cast<int>(std::ceil(size.y() / cell_)));
  grid_.assign(static_cast<size_t>(nx_) * ny_, {});
  auto index = [&](double x, double lo0, int n) {
    return std::clamp(static_cast<int>((x - lo0) / cell_), 0, n - 1);
  };
  for (std::uint32_t k = 0; k < triangles_.size(); ++k) {
    Eigen::Vector2d a = local_[triangles_[k][0]].head<2>(), b = a;
    for (int i = 1; i < 3; ++i) {
      a = a.cwiseMin(local_[triangles_[k][i]].head<2>());
      b = b.cwiseMax(local_[triangles_[k][i]].head<2>());
    }
    for (int y = index(a.y(), lo_.y(), ny_); y <= index(b.y(), lo_.y(), ny_); ++y)
      for (int x = index(a.x(), lo_.x(), nx_); x <= index(b.x(), lo_.x(), nx_); ++x)
        grid_[static_cast<size_t>(y) * nx_ + x].push_back(k);
  }
}

std::vector<LineCrossing> MeshLines::cross(const Eigen::Vector3d& point) const {
  std::vector<LineCrossing> out;
  if (grid_.empty()) return out;
  const Eigen::Vector2d p(point.dot(u_), point.dot(v_));
  const int x = static_cast<int>(std::floor((p.x() - lo_.x()) / cell_));
  const int y = static_cast<int>(std::floor((p.y() - lo_.y()) / cell_));
  if (x < 0 || y < 0 || x >= nx_ || y >= ny_) return out;
  const double t0 = point.dot(d_);
  for (std::uint32_t k : grid_[static_cast<size_t>(y) * nx_ + x]) {
    const Eigen::Vector3d& a = local_[triangles_[k][0]];
    const Eigen::Vector3d& b = local_[triangles_[k][1]];
    const Eigen::Vector3d& c = local_[triangles_[k][2]];
    // Barycentric coordinates of p in the projected triangle (either winding).
    const double det = (b.x() - a.x()) * (c.y() - a.y()) - (c.x() - a.x()) * (b.y() - a.y());
    if (std::abs(det) < 1e-18) continue;  // seen edge-on
    const double l1 = ((p.x() - a.x()) * (c.y() - a.y()) - (c.x() - a.x()) * (p.y() - a.y())) / det;
    const double l2 = ((b.x() - a.x()) * (p.y() - a.y()) - (p.x() - a.x()) * (b.y() - a.y())) / det;
    const double l0 = 1.0 - l1 - l2;
    if (l0 < 0 || l1 < 0 || l2 < 0) continue;
    out.push_back({l0 * a.z() + l1 * b.z() + l2 * c.z() - t0, normals_[k]});
  }
  std::sort(out.begin(), out.end(), [](const LineCrossing& a, const LineCrossing& b) { return a.t < b.t; });
  return out;
}

}  // namespace demoplan
