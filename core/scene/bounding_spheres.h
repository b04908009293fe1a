#pragma once
// A few spheres whose union covers every triangle of a mesh: the cheap bound the collision
// checker tests before FCL's exact narrow phase (see collision_checker.cpp).
//
// FCL collides a mesh as its triangles (a surface, not a solid), so covering the triangles is
// all a bound needs: if every sphere is separated from another body, so is every triangle, and
// FCL cannot find contact. A sphere that holds a triangle's three corners holds the triangle
// (spheres are convex); long triangles are split for the fit so that no sphere has to span the
// whole mesh. Radii carry a small margin against rounding in the fit and the tests.
#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <vector>

namespace demoplan {

struct BoundingSphere {
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  double radius = 0.0;
};

// Two levels below the whole: parts, and each part's children, which together hold the same
// triangles (pieces of them) as the part, more tightly.
struct SphereSet {
  BoundingSphere all;                  // holds every triangle (tested first)
  std::vector<BoundingSphere> parts;   // their union holds every triangle; empty: no bound
  std::vector<BoundingSphere> children;  // part i's: [children_begin[i], children_begin[i + 1])
  std::vector<int> children_begin;       // parts.size() + 1 entries
  // Triangle corners spread over the mesh (farthest-point order, at most kWitnesses): one that
  // lies inside a solid primitive proves contact (geometry_bounds.h, certainly_touching).
  std::vector<Eigen::Vector3d> witnesses;
  static constexpr int kWitnesses = 32;
  // Triangle edges, long ones spread over the mesh (at most kEdges): an edge lies in a
  // triangle, so one that crosses a solid primitive proves contact too, where no corner lies
  // inside (an arm through a thin board).
  std::vector<std::array<Eigen::Vector3d, 2>> edges;
  static constexpr int kEdges = 32;
};

// Radius margin added to every fitted sphere: 1 micrometre plus 1e-9 of the sphere's distance
// from the origin, far above the rounding of the fit, of placing the spheres in the world and
// of FCL's own tolerances, far below any clearance that matters.
double bounding_sphere_margin(const BoundingSphere& s);

// Spheres over the triangles (vertex indices into `vertices`, scale already applied), at most
// `max_parts` parts of at most `max_parts` children each (k-means clusters of the triangles'
// pieces, then of each part's). Deterministic.
SphereSet fit_bounding_spheres(const std::vector<Eigen::Vector3d>& vertices,
                               const std::vector<std::array<std::uint32_t, 3>>& triangles,
                               int max_parts = 16);

}  // namespace demoplan
