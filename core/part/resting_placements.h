#pragma once
// Where a part can rest on a flat surface, from its mesh alone: the faces of its convex hull on
// which it stands (its centre of mass projects inside them), each with its contact polygon,
// ranked by how far that projection lies from the face's border (how hard it is to tip over).
// What a user's own part gets in place of the benchmark SRDF's hand-made contact surfaces.
#include <string>
#include <vector>

#include <Eigen/Core>

#include "core/geometry/se3.h"
#include "core/model/mesh.h"

namespace demoplan {

struct RestingPlacementOptions {
  double min_area = 1e-4;        // m^2: smaller faces are left out (the facets of a curved side)
  double min_margin = 0.002;     // m: the centre of mass projects at least this far inside
  double coplanar_angle = 0.05;  // rad: hull facets this close in normal are one face
  double coplanar_distance = 0.001;  // m: ... and this close to each other's plane
  double contact_tolerance = 0.003;  // m: hull points this close to a face's plane touch the surface
};

struct RestingPlacement {
  std::vector<Eigen::Vector3d> polygon;  // the face, part frame, counter-clockwise seen from outside
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();  // outward, part frame
  double area = 0.0;    // m^2
  double margin = 0.0;  // m: centre of mass projection to the face's border
  double height = 0.0;  // m: centre of mass above the face
  // rad: how far the part tips about the nearest edge before it falls over: atan(margin / height)
  double tipping_angle = 0.0;
  // The part standing on this face on the plane z = 0, the face's centroid at the origin.
  Pose part_on_plane = Pose::Identity();
};

// The volume centroid of a closed mesh (the area centroid when it does not close), in the
// mesh's units times `scale`.
Eigen::Vector3d centre_of_mass(const TriangleMesh& mesh, double scale = 1.0);

// Placements of the convex hull of `points` (part frame, metres) for a part whose centre of
// mass is `com`, the stablest first. Throws std::invalid_argument when the points span no
// volume (fewer than 4, or all in a plane).
std::vector<RestingPlacement> resting_placements(const std::vector<Eigen::Vector3d>& points, const Eigen::Vector3d& com,
                                                 const RestingPlacementOptions& options = {});

}  // namespace demoplan
