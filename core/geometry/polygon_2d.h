#pragma once
// Plane polygons: the few operations the placement code needs.
#include <vector>

#include <Eigen/Core>

namespace demoplan {

// z of the cross product of two plane vectors.
inline double cross2(const Eigen::Vector2d& a, const Eigen::Vector2d& b) { return a.x() * b.y() - a.y() * b.x(); }

// Whether `point`, seen from above (x, y), lies inside or on the convex polygon, counter-clockwise
// seen from above (a support's or a tray's top); false for fewer than three vertices.
bool contains_from_above(const std::vector<Eigen::Vector3d>& polygon, const Eigen::Vector3d& point);

// Signed area: positive when counter-clockwise.
double polygon_area(const std::vector<Eigen::Vector2d>& polygon);

// Indices of the convex hull of the points, counter-clockwise, without collinear points
// (Andrew's monotone chain).
std::vector<int> hull_2d(const std::vector<Eigen::Vector2d>& points);

}  // namespace demoplan
