#pragma once
// The collision checker's conservative pre-test: bounds of a collision geometry (fitted spheres
// for a mesh, the exact shape for a box, cylinder or sphere) and a test that answers only
// "certainly separated". When it says so, FCL's exact narrow phase would find no contact (its
// meshes are their triangles, which the spheres cover); otherwise the caller asks FCL.
#include <Eigen/Core>
#include <cstddef>
#include <cstdint>
#include <memory>

#include "core/geometry/se3.h"
#include "core/scene/bounding_spheres.h"

namespace demoplan {

// What the pre-test knows of one geometry, in the geometry's own frame.
struct GeometryBound {
  enum class Kind { None, Mesh, Box, Cylinder, Sphere };
  Kind kind = Kind::None;  // None: no bound, always ask FCL
  // Box: half sizes; Cylinder (along z): radius, radius, half length; Sphere: radius, x3.
  Eigen::Vector3d half = Eigen::Vector3d::Zero();
  // Meshes: the fitted spheres; primitives: one sphere around the shape (margin included).
  std::shared_ptr<const SphereSet> spheres;

  // Sphere centres a placed bound carries: the whole's and the parts' (level 1), the children.
  std::size_t centre_count() const { return spheres ? 1 + spheres->parts.size() : 0; }
  std::size_t part_count() const { return spheres ? spheres->parts.size() : 0; }
  std::size_t child_count() const { return spheres ? spheres->children.size() : 0; }
};

GeometryBound box_bound(const Eigen::Vector3d& size);
GeometryBound cylinder_bound(double radius, double length);
GeometryBound sphere_bound(double radius);
GeometryBound mesh_bound(std::shared_ptr<const SphereSet> spheres);

// A bound at a world pose, with its sphere centres in the world: the whole's placed
// (place_centres), the parts' too or placed when a test first needs them (*parts_placed !=
// stamp), the children's placed per part when a test first needs them (child_placed[part] !=
// stamp); null stamps: all placed beforehand. Most pairs are told apart by the whole sphere.
struct PlacedBound {
  const GeometryBound* bound = nullptr;
  const Pose* pose = nullptr;
  Eigen::Vector3d* centres = nullptr;     // bound->centre_count() of them
  Eigen::Vector3d* children = nullptr;    // bound->child_count() of them
  std::uint64_t* child_placed = nullptr;  // bound->part_count() of them
  std::uint64_t stamp = 0;
  std::uint64_t* parts_placed = nullptr;  // one
};

// Writes bound.centre_count() world centres to `out`, or only the whole's (out[0]).
void place_centres(const GeometryBound& bound, const Pose& pose, Eigen::Vector3d* out);
void place_whole_centre(const GeometryBound& bound, const Pose& pose, Eigen::Vector3d* out);
// Writes bound.child_count() world centres to `out`.
void place_children(const GeometryBound& bound, const Pose& pose, Eigen::Vector3d* out);

// True only if the two placed bodies certainly do not touch.
bool certainly_separated(const PlacedBound& a, const PlacedBound& b);

// True only if they certainly touch as FCL sees them: a witness of one lies inside the other, a
// solid box, cylinder or sphere, by more than the margin: a corner (a mesh's triangle corner, a
// box's corner) or a point of an edge (a mesh's triangle edge, a box's edge). FCL tests a mesh's
// triangles and a box's solid against the solid primitive, so it finds that contact too. (Two
// meshes are never proven touching: FCL sees only surfaces.)
bool certainly_touching(const PlacedBound& a, const PlacedBound& b);

}  // namespace demoplan
