#pragma once
// Whether the points o + t d, t in [t_min, t_max], meet an axis-aligned box (the slab test):
// picking in the 3D view, lines of sight when a synthetic camera is placed.
#include <Eigen/Geometry>

namespace demoplan {

bool ray_hits_box(const Eigen::Vector3d& o, const Eigen::Vector3d& d, const Eigen::AlignedBox3d& box, double t_min,
                  double t_max);

}  // namespace demoplan
