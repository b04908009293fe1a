#include "core/cell/part_markers.h"

#include <Eigen/Geometry>
#include <cmath>
#include <set>
#include <sstream>

#include "core/error.h"

namespace demoplan {

namespace {

constexpr double kStandoff = 0.001;  // m in front of the face, as synth's box-face markers

// Whether the segment o + t d, t in [0, 1], meets the triangle (Moller-Trumbore).
bool segment_hits(const Eigen::Vector3d& o, const Eigen::Vector3d& d, const Eigen::Vector3d& a,
                  const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
  const Eigen::Vector3d e1 = b - a, e2 = c - a, p = d.cross(e2);
  const double det = e1.dot(p);
  if (std::abs(det) < 1e-15) return false;
  const Eigen::Vector3d s = o - a;
  const double u = s.dot(p) / det;
  if (u < 0 || u > 1) return false;
  const Eigen::Vector3d q = s.cross(e1);
  const double v = d.dot(q) / det;
  if (v < 0 || u + v > 1) return false;
  const double t = e2.dot(q) / det;
  return t >= 0 && t <= 1;
}

bool surface_near(const TriangleMesh& mesh, double scale, const Eigen::Vector3d& x, const Eigen::Vector3d& n,
                  double tolerance) {
  const Eigen::Vector3d o = x + tolerance * n, d = -2.0 * tolerance * n;
  for (const auto& t : mesh.triangles) {
    auto v = [&](int k) { return Eigen::Vector3d(mesh.vertices[t[k]].cast<double>() * scale); };
    if (segment_hits(o, d, v(0), v(1), v(2))) return true;
  }
  return false;
}

}  // namespace

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
  const Eigen::Vector3d z = normal.normalized();
  // The image's top edge along the part's +z, or +x where the face looks up or down.
  const Eigen::Vector3d up = std::abs(z.z()) > 0.9 ? Eigen::Vector3d::UnitX() : Eigen::Vector3d::UnitZ();
  const Eigen::Vector3d y = (up - up.dot(z) * z).normalized();
  const Eigen::Vector3d x = y.cross(z);

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
  m.pose.linear().col(0) = x;
  m.pose.linear().col(1) = y;
  m.pose.linear().col(2) = z;
  m.pose.translation() = point + kStandoff * z;
  return m;
}

}  // namespace demoplan
