#include "core/cell/part_markers.h"

#include <Eigen/Geometry>
#include <cmath>
#include <set>
#include <sstream>

#include "core/error.h"
#include "core/geometry/ray_triangle.h"

namespace demoplan {

namespace {

constexpr double kStandoff = 0.001;  // m in front of the face, as synth's box-face markers

// Some triangle of the mesh crosses the normal through x within `tolerance` of it.
bool surface_near(const TriangleMesh& mesh, double scale, const Eigen::Vector3d& x, const Eigen::Vector3d& n,
                  double tolerance) {
  const Eigen::Vector3d o = x + tolerance * n, d = -2.0 * tolerance * n;
  for (const auto& t : mesh.triangles) {
    auto v = [&](int k) { return Eigen::Vector3d(mesh.vertices[t[k]].cast<double>() * scale); };
    const std::optional<double> at = ray_triangle(o, d, v(0), v(1), v(2));
    if (at && *at >= 0 && *at <= 1) return true;
  }
  return false;
}

}  // namespace

Eigen::Matrix3d marker_frame_on_face(const Eigen::Vector3d& normal) {
  const Eigen::Vector3d z = normal.normalized();
  const Eigen::Vector3d up = std::abs(z.z()) > 0.9 ? Eigen::Vector3d::UnitX() : Eigen::Vector3d::UnitZ();
  Eigen::Matrix3d R;
  R.col(1) = (up - up.dot(z) * z).normalized();
  R.col(0) = R.col(1).cross(z);
  R.col(2) = z;
  return R;
}

int free_marker_id(const Cell& cell) {
  std::set<int> used;
  for (const auto& p : cell.parts)
    for (const auto& m : p.markers) used.insert(m.id);
  int id = 0;
  while (used.count(id)) ++id;
  return id;
}

CellMarker marker_on_face(const Cell& cell, int part, const TriangleMesh& mesh, const Eigen::Vector3d& point,
                          const Eigen::Vector3d& normal, double size, double flatness) {
  const CellPart& p = cell.parts.at(part);
  auto refuse = [&](const std::string& why) {
    throw InputError(cell.file, "parts[" + std::to_string(part) + "].markers",
                     "a marker on " + p.name + " " + why);
  };
  if (!(size > 0)) refuse("needs a size above 0 (it was " + std::to_string(size) + " m)");
  if (!point.allFinite() || !(normal.norm() > 1e-9)) refuse("needs a point on a face");
  const Eigen::Matrix3d R = marker_frame_on_face(normal);
  const Eigen::Vector3d x = R.col(0), y = R.col(1), z = R.col(2);

  const double h = 0.5 * size;
  for (const Eigen::Vector3d& corner : {Eigen::Vector3d(point + h * (x + y)), Eigen::Vector3d(point + h * (x - y)),
                                        Eigen::Vector3d(point - h * (x + y)), Eigen::Vector3d(point - h * (x - y))})
    if (!surface_near(mesh, p.scale, corner, z, flatness)) {
      std::ostringstream mm;
      mm << size * 1000.0;
      refuse("of " + mm.str() + " mm does not lie flat there (a corner is off the face by more than " +
             std::to_string(static_cast<int>(std::lround(flatness * 1000.0))) +
             " mm): click nearer the middle of a flat face, or make it smaller");
    }

  CellMarker m;
  m.id = free_marker_id(cell);
  m.size = size;
  m.pose.linear() = R;
  m.pose.translation() = point + kStandoff * z;
  return m;
}

}  // namespace demoplan
