#pragma once
// Where straight lines of one direction cross a triangle mesh: what a parallel-jaw gripper's
// closing line meets between its fingers. The triangles are binned once per direction on a grid
// over their projection, so a line tests only the few triangles it may cross.
#include <array>
#include <cstdint>
#include <vector>

#include <Eigen/Core>

namespace demoplan {

struct LineCrossing {
  double t = 0.0;            // along the direction, from the line's given point
  Eigen::Vector3d normal;    // unit normal of the crossed triangle (its winding's side)
};

class MeshLines {
public:
  // `direction` need not be unit length. `cells` grid cells along the longer side of the
  // projection.
  MeshLines(const std::vector<Eigen::Vector3d>& vertices, const std::vector<std::array<std::uint32_t, 3>>& triangles,
            const Eigen::Vector3d& direction, int cells = 64);

  // Every crossing of the line through `point`, sorted by t.
  std::vector<LineCrossing> cross(const Eigen::Vector3d& point) const;

  const Eigen::Vector3d& direction() const { return d_; }

private:
  Eigen::Vector3d d_, u_, v_;
  std::vector<Eigen::Vector3d> local_;  // vertices as (u, v, t)
  std::vector<std::array<std::uint32_t, 3>> triangles_;
  std::vector<Eigen::Vector3d> normals_;
  Eigen::Vector2d lo_ = Eigen::Vector2d::Zero();
  double cell_ = 1.0;
  int nx_ = 1, ny_ = 1;
  std::vector<std::vector<std::uint32_t>> grid_;  // triangles per cell, row-major
};

}  // namespace demoplan
