#include "core/scene/bounding_spheres.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace demoplan {

namespace {

using Vec = Eigen::Vector3d;

struct Piece {
  Vec a, b, c;
  Vec centroid() const { return (a + b + c) / 3.0; }
};

// The triangles cut (at the midpoint of the longest edge) until no edge is longer than
// max_edge: a cluster's sphere then never has to reach across the mesh for one long triangle.
// The pieces cover the triangles exactly, up to the rounding of a midpoint (within the margin).
std::vector<Piece> pieces(const std::vector<Vec>& vertices,
                          const std::vector<std::array<std::uint32_t, 3>>& triangles, double max_edge) {
  std::vector<Piece> out, stack;
  const double max2 = max_edge * max_edge;
  for (const auto& t : triangles) {
    stack.push_back({vertices[t[0]], vertices[t[1]], vertices[t[2]]});
    while (!stack.empty()) {
      Piece p = stack.back();
      stack.pop_back();
      const double ab = (p.b - p.a).squaredNorm(), bc = (p.c - p.b).squaredNorm(), ca = (p.a - p.c).squaredNorm();
      const double longest = std::max({ab, bc, ca});
      if (!(longest > max2)) {  // also ends on NaN
        out.push_back(p);
        continue;
      }
      if (ab == longest) {
        const Vec m = 0.5 * (p.a + p.b);
        stack.push_back({p.a, m, p.c});
        stack.push_back({m, p.b, p.c});
      } else if (bc == longest) {
        const Vec m = 0.5 * (p.b + p.c);
        stack.push_back({p.a, p.b, m});
        stack.push_back({p.a, m, p.c});
      } else {
        const Vec m = 0.5 * (p.c + p.a);
        stack.push_back({p.a, p.b, m});
        stack.push_back({m, p.b, p.c});
      }
    }
  }
  return out;
}

double max_distance(const std::vector<Vec>& points, const Vec& c, size_t* farthest = nullptr) {
  double best = 0.0;
  size_t at = 0;
  for (size_t i = 0; i < points.size(); ++i) {
    const double d = (points[i] - c).squaredNorm();
    if (d > best) best = d, at = i;
  }
  if (farthest) *farthest = at;
  return std::sqrt(best);
}

// A small sphere around the points: Ritter's start, refined by Badoiu-Clarkson steps towards
// the farthest point. Only the centre is approximate: the radius is the exact largest distance.
// The centre of many points is found from at most 4096 of them, evenly strided (the steps pass
// over the points 20 times; the radius, once over all of them, keeps the sphere enclosing).
BoundingSphere enclose(const std::vector<Vec>& all) {
  BoundingSphere s;
  if (all.empty()) return s;
  std::vector<Vec> strided;
  if (all.size() > 4096) {
    const size_t stride = (all.size() + 4095) / 4096;
    for (size_t i = 0; i < all.size(); i += stride) strided.push_back(all[i]);
  }
  const std::vector<Vec>& points = strided.empty() ? all : strided;
  size_t i1 = 0, i2 = 0;
  max_distance(points, points[0], &i1);
  max_distance(points, points[i1], &i2);
  Vec c = 0.5 * (points[i1] + points[i2]);
  double r = 0.5 * (points[i1] - points[i2]).norm();
  for (const Vec& p : points) {
    const double d = (p - c).norm();
    if (d > r) {
      const double grown = 0.5 * (r + d);
      c += (grown - r) / d * (p - c);
      r = grown;
    }
  }
  Vec best_c = c;
  double best_r = max_distance(points, c);
  for (int it = 1; it <= 16; ++it) {
    size_t far = 0;
    const double rad = max_distance(points, c, &far);
    if (rad < best_r) best_r = rad, best_c = c;
    c += (points[far] - c) / (it + 1.0);
  }
  s.centre = best_c;
  s.radius = max_distance(all, best_c);
  s.radius += bounding_sphere_margin(s);
  return s;
}

}  // namespace

double bounding_sphere_margin(const BoundingSphere& s) {
  return 1e-6 + 1e-9 * (s.centre.norm() + s.radius);
}

namespace {

// The index of the centre nearest to p (the first of equals).
int nearest_centre(const std::vector<Vec>& centres, const Vec& p) {
  int best = 0;
  double best_d = std::numeric_limits<double>::infinity();
  for (int c = 0; c < static_cast<int>(centres.size()); ++c) {
    const double d = (p - centres[static_cast<size_t>(c)]).squaredNorm();
    if (d < best_d) best_d = d, best = c;
  }
  return best;
}

// k-means (at most k clusters) of the pieces `idx` by their centroids, over at most 1024 evenly
// strided samples, seeded deterministically by farthest points. Empty clusters are dropped.
std::vector<std::vector<size_t>> clusters_of(const std::vector<Vec>& centroids, const std::vector<size_t>& idx, int k) {
  std::vector<Vec> samples;
  const size_t stride = std::max<size_t>(1, idx.size() / 1024);
  for (size_t i = 0; i < idx.size(); i += stride) samples.push_back(centroids[idx[i]]);
  k = std::max(1, std::min<int>(k, static_cast<int>(samples.size())));
  Vec mean = Vec::Zero();
  for (const Vec& p : samples) mean += p;
  mean /= static_cast<double>(samples.size());
  std::vector<Vec> centres;
  std::vector<double> nearest(samples.size());
  for (size_t i = 0; i < samples.size(); ++i) nearest[i] = (samples[i] - mean).squaredNorm();
  for (int c = 0; c < k; ++c) {
    const size_t far = static_cast<size_t>(std::max_element(nearest.begin(), nearest.end()) - nearest.begin());
    centres.push_back(samples[far]);
    for (size_t i = 0; i < samples.size(); ++i)
      nearest[i] = c == 0 ? (samples[i] - centres[0]).squaredNorm()
                          : std::min(nearest[i], (samples[i] - centres.back()).squaredNorm());
  }
  // Up to 10 rounds; once a round assigns every sample as the last did, its centres are the
  // last round's to the bit, and so would every further round's be.
  std::vector<int> assigned(samples.size(), -1);
  for (int it = 0; it < 10; ++it) {
    std::vector<Vec> sum(centres.size(), Vec::Zero());
    std::vector<int> count(centres.size(), 0);
    bool changed = false;
    for (size_t i = 0; i < samples.size(); ++i) {
      const int c = nearest_centre(centres, samples[i]);
      changed |= c != assigned[i];
      assigned[i] = c;
      sum[static_cast<size_t>(c)] += samples[i];
      ++count[static_cast<size_t>(c)];
    }
    if (!changed) break;
    for (size_t c = 0; c < centres.size(); ++c)
      if (count[c] > 0) centres[c] = sum[c] / count[c];
  }
  std::vector<std::vector<size_t>> out(centres.size());
  for (size_t i : idx) out[static_cast<size_t>(nearest_centre(centres, centroids[i]))].push_back(i);
  out.erase(std::remove_if(out.begin(), out.end(), [](const auto& c) { return c.empty(); }), out.end());
  return out;
}

// The sphere around every corner of the pieces `idx`.
BoundingSphere enclose_pieces(const std::vector<Piece>& ps, const std::vector<size_t>& idx) {
  std::vector<Vec> corners;
  corners.reserve(3 * idx.size());
  for (size_t i : idx) {
    corners.push_back(ps[i].a);
    corners.push_back(ps[i].b);
    corners.push_back(ps[i].c);
  }
  return enclose(corners);
}

// Up to `count` edges of the triangles: each time the edge that is longest plus farthest (its
// midpoint from the chosen ones' midpoints), so that long edges come first and spread over the
// mesh. The endpoints are the mesh's own vertices, as FCL's triangles have them.
std::vector<std::array<Vec, 2>> long_spread_edges(const std::vector<Vec>& vertices,
                                                  const std::vector<std::array<std::uint32_t, 3>>& triangles,
                                                  int count) {
  std::vector<std::pair<std::uint32_t, std::uint32_t>> unique;
  unique.reserve(3 * triangles.size());
  for (const auto& t : triangles)
    for (int k = 0; k < 3; ++k) unique.emplace_back(std::minmax(t[k], t[(k + 1) % 3]));
  std::sort(unique.begin(), unique.end());
  unique.erase(std::unique(unique.begin(), unique.end()), unique.end());
  std::vector<double> length(unique.size()), gap(unique.size(), std::numeric_limits<double>::infinity());
  std::vector<Vec> mid(unique.size());
  for (size_t i = 0; i < unique.size(); ++i) {
    const Vec& a = vertices[unique[i].first];
    const Vec& b = vertices[unique[i].second];
    length[i] = (b - a).norm();
    mid[i] = 0.5 * (a + b);
  }
  std::vector<std::array<Vec, 2>> out;
  std::vector<char> taken(unique.size(), 0);
  while (out.size() < static_cast<size_t>(count)) {
    size_t best = unique.size();
    double best_score = -1.0;
    for (size_t i = 0; i < unique.size(); ++i) {
      if (taken[i] || !(length[i] > 0.0)) continue;
      const double score = length[i] + (out.empty() ? 0.0 : std::sqrt(gap[i]));
      if (score > best_score) best_score = score, best = i;
    }
    if (best == unique.size()) break;  // every edge chosen
    taken[best] = 1;
    out.push_back({vertices[unique[best].first], vertices[unique[best].second]});
    for (size_t i = 0; i < unique.size(); ++i) gap[i] = std::min(gap[i], (mid[i] - mid[best]).squaredNorm());
  }
  return out;
}

}  // namespace

SphereSet fit_bounding_spheres(const std::vector<Eigen::Vector3d>& vertices,
                               const std::vector<std::array<std::uint32_t, 3>>& triangles, int max_parts) {
  SphereSet set;
  std::vector<Vec> used;  // the vertices of the triangles, each once
  std::vector<char> seen(vertices.size(), 0);
  for (const auto& t : triangles)
    for (int k = 0; k < 3; ++k) {
      if (t[k] >= vertices.size() || !vertices[t[k]].allFinite()) return {};  // no bound: FCL decides
      if (!seen[t[k]]) seen[t[k]] = 1, used.push_back(vertices[t[k]]);
    }
  if (used.empty()) return {};
  set.all = enclose(used);

  // Pieces no longer than 1/48 of the mesh's diameter, fewer if that would make too many.
  double max_edge = std::max(2.0 * set.all.radius / 48.0, 1e-9);
  std::vector<Piece> ps = pieces(vertices, triangles, max_edge);
  while (ps.size() > 200'000) {
    max_edge *= 2.0;
    ps = pieces(vertices, triangles, max_edge);
  }
  std::vector<size_t> every(ps.size());
  std::vector<Vec> centroids(ps.size());
  for (size_t i = 0; i < ps.size(); ++i) every[i] = i, centroids[i] = ps[i].centroid();
  // Each part's pieces clustered again: the part's children.
  for (const auto& part : clusters_of(centroids, every, max_parts)) {
    set.parts.push_back(enclose_pieces(ps, part));
    set.children_begin.push_back(static_cast<int>(set.children.size()));
    for (const auto& child : clusters_of(centroids, part, max_parts)) set.children.push_back(enclose_pieces(ps, child));
  }
  set.children_begin.push_back(static_cast<int>(set.children.size()));

  // Witnesses: the corner farthest from the centre, then each time the corner farthest from
  // those chosen.
  std::vector<double> gap(used.size(), std::numeric_limits<double>::infinity());
  size_t next = 0;
  max_distance(used, set.all.centre, &next);
  while (set.witnesses.size() < static_cast<size_t>(SphereSet::kWitnesses)) {
    const Vec w = used[next];
    set.witnesses.push_back(w);
    double far = 0.0;
    for (size_t i = 0; i < used.size(); ++i) {
      gap[i] = std::min(gap[i], (used[i] - w).squaredNorm());
      if (gap[i] > far) far = gap[i], next = i;
    }
    if (far == 0.0) break;  // every corner chosen
  }
  set.edges = long_spread_edges(vertices, triangles, SphereSet::kEdges);
  return set;
}

}  // namespace demoplan
