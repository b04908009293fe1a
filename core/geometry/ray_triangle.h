#pragma once
// Where the line o + t d meets a triangle (Moller-Trumbore): picking in the 3D view, checking
// that a marker lies flat on a part's face.
#include <Eigen/Core>
#include <optional>

namespace demoplan {

// The t at which o + t d crosses the triangle (a, b, c), any sign; none when it misses or runs
// parallel to it. t is in units of d (d need not be normalised).
std::optional<double> ray_triangle(const Eigen::Vector3d& o, const Eigen::Vector3d& d, const Eigen::Vector3d& a,
                                   const Eigen::Vector3d& b, const Eigen::Vector3d& c);

}  // namespace demoplan
