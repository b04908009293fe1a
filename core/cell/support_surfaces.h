#pragma once
// Where parts can be put down on a piece of furniture given as a mesh: its upward-facing flat
// regions above a minimum area, as convex polygons (the placement test, support.h, needs convex
// supports). A region that fills its convex hull becomes the hull; an L- or U-shaped one is cut
// into convex pieces by merging its triangles across shared edges while the union stays convex.
#include <array>
#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "core/geometry/se3.h"

namespace demoplan {

struct SupportSurfaceOptions {
  double min_area = 0.01;          // m^2
  double max_tilt = 0.05;          // rad from horizontal
  double height_tolerance = 0.002;  // m: faces this close in height are one region
};

// `vertices` in the mesh frame, metres; `world_T_mesh` says which way is up. Polygons in the mesh
// frame, counter-clockwise seen from above, the largest region first.
std::vector<std::vector<Eigen::Vector3d>> support_surfaces(const std::vector<Eigen::Vector3d>& vertices,
                                                           const std::vector<std::array<std::uint32_t, 3>>& triangles,
                                                           const Pose& world_T_mesh,
                                                           const SupportSurfaceOptions& options = {});

}  // namespace demoplan
