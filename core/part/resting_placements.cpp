#include "core/part/resting_placements.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <stdexcept>

#include "core/geometry/polygon_2d.h"

extern "C" {
#include <libqhull_r/qhull_ra.h>
}

namespace demoplan {

namespace {

struct HullFacet {
  Eigen::Vector3d normal;  // outward
  double offset = 0.0;     // plane: normal . x = offset
  std::vector<Eigen::Vector3d> vertices;
};

// The hull's facets from Qhull, with coplanar facets merged by Qhull itself (its pre-merge on
// the angle and centrum distance), so a flat face of a scanned part comes out as one polygon.
std::vector<HullFacet> hull_facets(const std::vector<Eigen::Vector3d>& points, const RestingPlacementOptions& o) {
  std::vector<coordT> coords;
  coords.reserve(points.size() * 3);
  for (const auto& p : points) coords.insert(coords.end(), {p.x(), p.y(), p.z()});
  char options[128];
  std::snprintf(options, sizeof options, "qhull Qx C-%g A-%g", o.coplanar_distance, std::cos(o.coplanar_angle));
  std::unique_ptr<FILE, int (*)(FILE*)> sink(std::fopen("/dev/null", "w"), &std::fclose);
  qhT qh_storage;
  qhT* qh = &qh_storage;
  qh_zero(qh, sink.get());
  const int code = qh_new_qhull(qh, 3, static_cast<int>(points.size()), coords.data(), False, options, nullptr,
                                sink.get());
  std::vector<HullFacet> out;
  if (code == 0) {
    facetT* facet;
    FORALLfacets {
      HullFacet f;
      f.normal = Eigen::Vector3d(facet->normal[0], facet->normal[1], facet->normal[2]).normalized();
      f.offset = -facet->offset;
      vertexT *vertex, **vertexp;
      FOREACHvertex_(facet->vertices) f.vertices.emplace_back(vertex->point[0], vertex->point[1], vertex->point[2]);
      out.push_back(std::move(f));
    }
  }
  qh_freeqhull(qh, !qh_ALL);
  int still_long = 0, still_total = 0;
  qh_memfreeshort(qh, &still_long, &still_total);
  if (code != 0 || out.size() < 4)
    throw std::invalid_argument("the points span no volume (" + std::to_string(points.size()) +
                                " points; all in a plane or fewer than 4)");
  return out;
}

// Orthonormal axes of the plane with normal n.
std::pair<Eigen::Vector3d, Eigen::Vector3d> plane_axes(const Eigen::Vector3d& n) {
  const Eigen::Vector3d a = std::abs(n.x()) < 0.9 ? Eigen::Vector3d::UnitX() : Eigen::Vector3d::UnitY();
  const Eigen::Vector3d u = n.cross(a).normalized();
  return {u, n.cross(u)};
}


// Distance from p to the segment [a, b].
double segment_distance(const Eigen::Vector2d& p, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  const Eigen::Vector2d d = b - a;
  const double t = d.squaredNorm() > 0 ? std::clamp((p - a).dot(d) / d.squaredNorm(), 0.0, 1.0) : 0.0;
  return (a + t * d - p).norm();
}

}  // namespace

Eigen::Vector3d centre_of_mass(const TriangleMesh& mesh, double scale) {
  double volume = 0.0, area = 0.0;
  Eigen::Vector3d moment = Eigen::Vector3d::Zero(), surface = Eigen::Vector3d::Zero();
  for (const auto& t : mesh.triangles) {
    const Eigen::Vector3d a = mesh.vertices[t[0]].cast<double>() * scale;
    const Eigen::Vector3d b = mesh.vertices[t[1]].cast<double>() * scale;
    const Eigen::Vector3d c = mesh.vertices[t[2]].cast<double>() * scale;
    const double v = a.dot(b.cross(c)) / 6.0;  // signed volume of the tetrahedron with the origin
    volume += v;
    moment += v * (a + b + c) / 4.0;
    const double s = 0.5 * (b - a).cross(c - a).norm();
    area += s;
    surface += s * (a + b + c) / 3.0;
  }
  // A mesh that does not close (or is inside out in places) has a volume far from its size.
  const Eigen::AlignedBox3f box = mesh.bounds();
  const double box_volume = (box.sizes().cast<double>() * scale).prod();
  if (std::abs(volume) > 1e-3 * box_volume && std::abs(volume) <= box_volume * 1.0001) return moment / volume;
  return area > 0 ? Eigen::Vector3d(surface / area) : Eigen::Vector3d(box.center().cast<double>() * scale);
}

std::vector<RestingPlacement> resting_placements(const std::vector<Eigen::Vector3d>& points, const Eigen::Vector3d& com,
                                                 const RestingPlacementOptions& o) {
  const std::vector<HullFacet> facets = hull_facets(points, o);
  std::vector<RestingPlacement> out;
  for (HullFacet f : facets) {
    // A merged facet's plane may cut through the points it merged (by up to the merge distance):
    // the part rests on the parallel plane through its outermost point.
    for (const auto& p : points) f.offset = std::max(f.offset, f.normal.dot(p));
    // A real face is not flat to the micrometre (a scan, a warped box): the part touches the
    // surface with every hull point within the contact tolerance of the facet's plane.
    const auto [u, v] = plane_axes(f.normal);
    std::vector<Eigen::Vector3d> touching;
    for (const auto& p : points)
      if (f.offset - f.normal.dot(p) <= o.contact_tolerance) touching.push_back(p);
    Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
    for (const auto& p : touching) centroid += p;
    centroid /= static_cast<double>(touching.size());
    centroid += (f.offset - f.normal.dot(centroid)) * f.normal;  // onto the plane
    std::vector<Eigen::Vector2d> flat;
    for (const auto& p : touching) flat.emplace_back((p - centroid).dot(u), (p - centroid).dot(v));
    const std::vector<int> ring = hull_2d(flat);
    if (ring.size() < 3) continue;
    std::vector<Eigen::Vector2d> poly2;
    std::vector<Eigen::Vector3d> poly;
    for (int i : ring) {
      poly2.push_back(flat[i]);
      poly.push_back(centroid + flat[i].x() * u + flat[i].y() * v);
    }
    const double area = polygon_area(poly2);
    if (area < o.min_area) continue;
    // The centre of mass projected onto the face: inside it by `margin`, or the part tips over.
    const double height = f.offset - f.normal.dot(com);
    const Eigen::Vector3d foot = com + height * f.normal;
    const Eigen::Vector2d p((foot - centroid).dot(u), (foot - centroid).dot(v));
    double margin = std::numeric_limits<double>::infinity();
    bool inside = true;
    for (size_t i = 0; i < poly2.size(); ++i) {
      const auto& a = poly2[i];
      const auto& b = poly2[(i + 1) % poly2.size()];
      if (cross2(b - a, p - a) < 0) inside = false;
      margin = std::min(margin, segment_distance(p, a, b));
    }
    if (!inside || margin < o.min_margin || height <= 0) continue;
    // Facets of one face give the same placement: keep the one that holds best.
    bool duplicate = false;
    for (RestingPlacement& r : out)
      if (r.normal.dot(f.normal) > std::cos(o.coplanar_angle)) {
        duplicate = true;
        if (margin <= r.margin) break;
        r.polygon.clear();  // replaced below
      }
    if (duplicate && !std::any_of(out.begin(), out.end(), [](auto& r) { return r.polygon.empty(); })) continue;
    out.erase(std::remove_if(out.begin(), out.end(), [](auto& r) { return r.polygon.empty(); }), out.end());
    RestingPlacement r;
    r.polygon = poly;
    r.normal = f.normal;
    r.area = area;
    r.margin = margin;
    r.height = height;
    r.tipping_angle = std::atan2(margin, height);
    // Rotate the outward normal onto -z; the face's centroid goes to the origin.
    const Eigen::Matrix3d R = Eigen::Quaterniond::FromTwoVectors(f.normal, -Eigen::Vector3d::UnitZ()).toRotationMatrix();
    r.part_on_plane.linear() = R;
    r.part_on_plane.translation() = -R * centroid;
    out.push_back(std::move(r));
  }
  std::stable_sort(out.begin(), out.end(), [](auto& a, auto& b) { return a.margin > b.margin; });
  return out;
}

}  // namespace demoplan
