#pragma once
// Where objects may rest, and the benchmark's test of whether an object rests there
// (gtamp README 6, "Placement test"): some polygon of the object's contact surface lies
// within a thin slab above some support polygon and projects inside it.
#include <string>
#include <vector>

#include "core/scene/scene.h"

namespace demoplan {

struct SupportPolygon {
  std::string name;      // "<furniture>/<contact>" or "robot/<contact>"
  int furniture = -1;    // furniture index, or -1 for a robot surface
  int robot_link = -1;   // robot link carrying it (robot surfaces only)
  std::vector<Eigen::Vector3d> vertices;  // in the carrying link's frame, counter-clockwise from +normal
};

// Every furniture contact polygon (SRDF <contact>) and every robot contact polygon.
std::vector<SupportPolygon> support_polygons(const Scene& scene);
// The furniture's alone, as world polygons: where a measured rest is settled.
std::vector<std::vector<Eigen::Vector3d>> furniture_support_polygons(const Scene& scene);

// The benchmark's plane of a polygon: origin at its first vertex, normal the normalised cross
// product of the pair of edge vectors from the first vertex with the largest cross product.
struct PolygonPlane {
  Eigen::Vector3d origin, normal, u, v;  // u, v span the plane; (u, v, normal) right-handed
};
PolygonPlane polygon_plane(const std::vector<Eigen::Vector3d>& world_vertices);

// Inclusive point-in-convex-polygon test after projection onto the plane.
bool projects_inside(const PolygonPlane& plane, const std::vector<Eigen::Vector3d>& polygon,
                     const Eigen::Vector3d& point, double tol = 1e-12);

struct PlacementTolerance {
  double lower = -0.0001;  // m, signed distance of every object vertex along the normal
  double upper = 0.002;
};

struct PlacementCheck {
  bool placed = false;
  int support = -1;        // index into support_polygons(scene)
  int object_polygon = -1; // index into the object's contact polygons
};

// Object contact polygons in the object frame (all SRDF contacts of the object).
std::vector<std::vector<Eigen::Vector3d>> object_contact_polygons(const SceneObject& object);

// Whether `object` at world pose `pose` rests on a support; robot surfaces are placed with
// the robot's link poses.
PlacementCheck check_placement(const Scene& scene, const std::vector<SupportPolygon>& supports,
                                const PoseVector& robot_link_poses, int object, const Pose& pose,
                                const PlacementTolerance& tol = {});

}  // namespace demoplan
