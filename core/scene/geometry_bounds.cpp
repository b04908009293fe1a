#include "core/scene/geometry_bounds.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <utility>
#include <vector>

#include "core/geometry/box_overlap.h"

namespace demoplan {

namespace {

using Vec = Eigen::Vector3d;

GeometryBound primitive(GeometryBound::Kind kind, const Vec& half, double circumradius,
                        std::vector<Vec> witnesses = {}, std::vector<std::array<Vec, 2>> edges = {}) {
  GeometryBound b;
  b.kind = kind;
  b.half = half;
  auto set = std::make_shared<SphereSet>();
  set->all.radius = circumradius;
  set->all.radius += bounding_sphere_margin(set->all);
  set->parts = {set->all};
  set->children = {set->all};
  set->children_begin = {0, 1};
  set->witnesses = std::move(witnesses);
  set->edges = std::move(edges);
  b.spheres = std::move(set);
  return b;
}

bool spheres_apart(const Vec& ca, double ra, const Vec& cb, double rb) {
  const double r = ra + rb;
  return (ca - cb).squaredNorm() > r * r;
}

// Squared distance from a point in the primitive's frame to the solid primitive.
double squared_distance(const GeometryBound& p, const Vec& x) {
  switch (p.kind) {
    case GeometryBound::Kind::Box:
      return (x.cwiseAbs() - p.half).cwiseMax(0.0).squaredNorm();
    case GeometryBound::Kind::Cylinder: {
      const double radial = std::max(std::sqrt(x.x() * x.x() + x.y() * x.y()) - p.half.x(), 0.0);
      const double axial = std::max(std::abs(x.z()) - p.half.z(), 0.0);
      return radial * radial + axial * axial;
    }
    case GeometryBound::Kind::Sphere: {
      const double d = std::max(x.norm() - p.half.x(), 0.0);
      return d * d;
    }
    default:
      return 0.0;
  }
}

// The world centres of the whole (index 0) and the parts (1...), the parts placed now if this
// query has not yet.
const Vec* centres_of(const PlacedBound& b) {
  if (b.parts_placed && *b.parts_placed != b.stamp) {
    const SphereSet& s = *b.bound->spheres;
    for (size_t i = 0; i < s.parts.size(); ++i) b.centres[1 + i] = *b.pose * s.parts[i].centre;
    *b.parts_placed = b.stamp;
  }
  return b.centres;
}

// The world centres of part `i`'s children, placed now if this query has not yet.
const Vec* children_of(const PlacedBound& b, size_t i) {
  const SphereSet& s = *b.bound->spheres;
  const int begin = s.children_begin[i], end = s.children_begin[i + 1];
  if (b.child_placed && b.child_placed[i] != b.stamp) {
    for (int k = begin; k < end; ++k) b.children[k] = *b.pose * s.children[k].centre;
    b.child_placed[i] = b.stamp;
  }
  return b.children;
}

// Every sphere of `a` against the exact primitive `p`, coarse to fine: the whole, each part,
// and a part's children only when the part may touch.
bool spheres_apart_from_primitive(const PlacedBound& a, const PlacedBound& p) {
  const Eigen::Matrix3d Rt = p.pose->linear().transpose();
  const Vec t = p.pose->translation();
  auto apart = [&](const Vec& centre, double radius) {
    return squared_distance(*p.bound, Rt * (centre - t)) > radius * radius;
  };
  const SphereSet& s = *a.bound->spheres;
  if (apart(a.centres[0], s.all.radius)) return true;
  const Vec* centres = centres_of(a);
  for (size_t i = 0; i < s.parts.size(); ++i) {
    if (apart(centres[1 + i], s.parts[i].radius)) continue;
    const Vec* c = children_of(a, i);
    for (int k = s.children_begin[i]; k < s.children_begin[i + 1]; ++k)
      if (!apart(c[k], s.children[k].radius)) return false;
  }
  return true;
}

bool sphere_sets_apart(const PlacedBound& a, const PlacedBound& b) {
  const SphereSet& sa = *a.bound->spheres;
  const SphereSet& sb = *b.bound->spheres;
  if (spheres_apart(a.centres[0], sa.all.radius, b.centres[0], sb.all.radius)) return true;
  const Vec* a_centres = centres_of(a);
  const Vec* b_centres = nullptr;
  for (size_t i = 0; i < sa.parts.size(); ++i) {
    const Vec& ca = a_centres[1 + i];
    const double ra = sa.parts[i].radius;
    if (spheres_apart(ca, ra, b.centres[0], sb.all.radius)) continue;
    if (!b_centres) b_centres = centres_of(b);
    for (size_t j = 0; j < sb.parts.size(); ++j) {
      const Vec& cb = b_centres[1 + j];
      const double rb = sb.parts[j].radius;
      if (spheres_apart(ca, ra, cb, rb)) continue;
      // Parts i and j may touch: part i's children against part j, then against its children.
      const Vec* ka = children_of(a, i);
      const Vec* kb = nullptr;
      for (int x = sa.children_begin[i]; x < sa.children_begin[i + 1]; ++x) {
        const double rx = sa.children[x].radius;
        if (spheres_apart(ka[x], rx, cb, rb)) continue;
        if (!kb) kb = children_of(b, j);
        for (int y = sb.children_begin[j]; y < sb.children_begin[j + 1]; ++y)
          if (!spheres_apart(ka[x], rx, kb[y], sb.children[y].radius)) return false;
      }
    }
  }
  return true;
}

// How far apart two placed bodies must be proven (or how deep a corner must lie) to answer
// without FCL: as the spheres' margin, 1 um plus 1e-9 of the distances from the origin.
double margin_between(const PlacedBound& a, const PlacedBound& b) {
  return 1e-6 + 1e-9 * (a.pose->translation().norm() + b.pose->translation().norm());
}

// Two boxes by the separating axis test (core/geometry/box_overlap.h), one grown by the
// margin: exact, so a base box beside a table's legs or under its top is told apart without
// FCL, where the boxes' bounding spheres overlap.
bool boxes_apart(const PlacedBound& a, const PlacedBound& b) {
  return !boxes_overlap(*a.pose, a.bound->half + Vec::Constant(margin_between(a, b)), *b.pose, b.bound->half);
}

bool is_primitive(const GeometryBound& b) {
  return b.kind == GeometryBound::Kind::Box || b.kind == GeometryBound::Kind::Cylinder ||
         b.kind == GeometryBound::Kind::Sphere;
}

// How deep a point (in the primitive's frame) lies inside the solid primitive; negative outside.
double depth_inside(const GeometryBound& p, const Vec& x) {
  switch (p.kind) {
    case GeometryBound::Kind::Box:
      return (p.half - x.cwiseAbs()).minCoeff();
    case GeometryBound::Kind::Cylinder:
      return std::min(p.half.x() - std::hypot(x.x(), x.y()), p.half.z() - std::abs(x.z()));
    case GeometryBound::Kind::Sphere:
      return p.half.x() - x.norm();
    default:
      return -1.0;
  }
}

// A candidate for the deepest point of the segment [a, b] (in the primitive's frame) inside the
// solid primitive `p`, or nothing when the segment misses `p` shrunk by `shrink`: the middle of
// the part inside the shrunk box (box; the cylinder's end caps), the point nearest the axis
// (cylinder) or the centre (sphere). Only a search: the caller checks the point's depth.
std::optional<Vec> probe_point(const GeometryBound& p, const Vec& a, const Vec& b, double shrink) {
  const Vec d = b - a;
  double lo = 0.0, hi = 1.0;
  auto clip = [&](int k, double half) {  // keep the t where |a[k] + t d[k]| < half
    if (!(half > 0.0)) return false;
    if (d[k] == 0.0) return std::abs(a[k]) < half;
    double t1 = (-half - a[k]) / d[k], t2 = (half - a[k]) / d[k];
    if (t1 > t2) std::swap(t1, t2);
    lo = std::max(lo, t1);
    hi = std::min(hi, t2);
    return lo < hi;
  };
  auto nearest = [&](const Vec& dir, const Vec& from) {  // t of the point nearest the origin, in [lo, hi]
    const double dd = dir.squaredNorm();
    return dd > 0.0 ? std::clamp(-from.dot(dir) / dd, lo, hi) : 0.5 * (lo + hi);
  };
  switch (p.kind) {
    case GeometryBound::Kind::Box:
      for (int k = 0; k < 3; ++k)
        if (!clip(k, p.half[k] - shrink)) return std::nullopt;
      return a + 0.5 * (lo + hi) * d;
    case GeometryBound::Kind::Cylinder: {
      if (!clip(2, p.half.z() - shrink)) return std::nullopt;
      return a + nearest(Vec(d.x(), d.y(), 0.0), Vec(a.x(), a.y(), 0.0)) * d;
    }
    case GeometryBound::Kind::Sphere:
      return a + nearest(d, a) * d;
    default:
      return std::nullopt;
  }
}

// Some witness of `w` inside the solid primitive `p`: a corner, or a point of an edge (a mesh's
// triangle edge, a box's edge), deeper than the margin.
bool witness_inside(const PlacedBound& w, const PlacedBound& p) {
  if (!is_primitive(*p.bound) || !w.bound->spheres) return false;
  const SphereSet& s = *w.bound->spheres;
  if (s.witnesses.empty() && s.edges.empty()) return false;
  const Eigen::Matrix3d Rt = p.pose->linear().transpose();
  const Eigen::Matrix3d R = Rt * w.pose->linear();
  const Vec t = Rt * (w.pose->translation() - p.pose->translation());
  const double margin = margin_between(w, p);
  for (const Vec& v : s.witnesses)
    if (depth_inside(*p.bound, R * v + t) > margin) return true;
  for (const auto& [a, b] : s.edges) {
    const std::optional<Vec> x = probe_point(*p.bound, R * a + t, R * b + t, 2.0 * margin);
    if (x && depth_inside(*p.bound, *x) > margin) return true;
  }
  return false;
}

}  // namespace

GeometryBound box_bound(const Eigen::Vector3d& size) {
  const Vec half = 0.5 * size;
  std::vector<Vec> corners;
  for (int i = 0; i < 8; ++i)
    corners.emplace_back(i & 1 ? half.x() : -half.x(), i & 2 ? half.y() : -half.y(), i & 4 ? half.z() : -half.z());
  // Its 12 edges: corners i and i + 2^k that differ along axis k only.
  std::vector<std::array<Vec, 2>> edges;
  for (int i = 0; i < 8; ++i)
    for (int k = 0; k < 3; ++k)
      if (!(i & (1 << k))) edges.push_back({corners[i], corners[i | (1 << k)]});
  return primitive(GeometryBound::Kind::Box, half, half.norm(), std::move(corners), std::move(edges));
}

GeometryBound cylinder_bound(double radius, double length) {
  return primitive(GeometryBound::Kind::Cylinder, Vec(radius, radius, 0.5 * length), std::hypot(radius, 0.5 * length));
}

GeometryBound sphere_bound(double radius) {
  return primitive(GeometryBound::Kind::Sphere, Vec::Constant(radius), radius);
}

GeometryBound mesh_bound(std::shared_ptr<const SphereSet> spheres) {
  GeometryBound b;
  if (!spheres || spheres->parts.empty()) return b;  // Kind::None
  b.kind = GeometryBound::Kind::Mesh;
  b.spheres = std::move(spheres);
  return b;
}

void place_whole_centre(const GeometryBound& bound, const Pose& pose, Eigen::Vector3d* out) {
  if (bound.spheres) out[0] = pose * bound.spheres->all.centre;
}

void place_centres(const GeometryBound& bound, const Pose& pose, Eigen::Vector3d* out) {
  if (!bound.spheres) return;
  out[0] = pose * bound.spheres->all.centre;
  for (size_t i = 0; i < bound.spheres->parts.size(); ++i) out[1 + i] = pose * bound.spheres->parts[i].centre;
}

void place_children(const GeometryBound& bound, const Pose& pose, Eigen::Vector3d* out) {
  if (!bound.spheres) return;
  for (size_t i = 0; i < bound.spheres->children.size(); ++i) out[i] = pose * bound.spheres->children[i].centre;
}

bool certainly_separated(const PlacedBound& a, const PlacedBound& b) {
  if (a.bound->kind == GeometryBound::Kind::None || b.bound->kind == GeometryBound::Kind::None) return false;
  if (a.bound->kind == GeometryBound::Kind::Box && b.bound->kind == GeometryBound::Kind::Box)
    return spheres_apart(a.centres[0], a.bound->spheres->all.radius, b.centres[0], b.bound->spheres->all.radius) ||
           boxes_apart(a, b);
  if (is_primitive(*b.bound)) return spheres_apart_from_primitive(a, b);
  if (is_primitive(*a.bound)) return spheres_apart_from_primitive(b, a);
  return sphere_sets_apart(a, b);
}

bool certainly_touching(const PlacedBound& a, const PlacedBound& b) {
  if (a.bound->kind == GeometryBound::Kind::None || b.bound->kind == GeometryBound::Kind::None) return false;
  return witness_inside(a, b) || witness_inside(b, a);
}

}  // namespace demoplan
