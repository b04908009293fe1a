#include "core/cell/support_surfaces.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>

#include "core/geometry/polygon_2d.h"

namespace demoplan {

namespace {

using Vec2 = Eigen::Vector2d;

// Convex pieces of a region given as counter-clockwise triangles over shared vertex ids:
// neighbours across a shared edge are merged while the union stays convex (Hertel-Mehlhorn).
std::vector<std::vector<int>> convex_pieces(std::vector<std::vector<int>> polys, const std::vector<Vec2>& at) {
  auto convex = [&](const std::vector<int>& poly) {
    for (size_t i = 0; i < poly.size(); ++i) {
      const Vec2& a = at[poly[i]];
      const Vec2& b = at[poly[(i + 1) % poly.size()]];
      const Vec2& c = at[poly[(i + 2) % poly.size()]];
      if (cross2(b - a, c - b) < -1e-12) return false;
    }
    return true;
  };
  for (bool merged = true; merged;) {
    merged = false;
    for (size_t i = 0; i < polys.size() && !merged; ++i)
      for (size_t j = i + 1; j < polys.size() && !merged; ++j) {
        const auto& P = polys[i];
        const auto& Q = polys[j];
        for (size_t a = 0; a < P.size() && !merged; ++a)
          for (size_t b = 0; b < Q.size() && !merged; ++b) {
            // P has edge u->v and Q has v->u.
            if (P[a] != Q[(b + 1) % Q.size()] || P[(a + 1) % P.size()] != Q[b]) continue;
            std::vector<int> u;
            for (size_t k = 0; k <= a; ++k) u.push_back(P[k]);
            for (size_t k = 2; k < Q.size(); ++k) u.push_back(Q[(b + k) % Q.size()]);
            for (size_t k = a + 1; k < P.size(); ++k) u.push_back(P[k]);
            if (!convex(u)) continue;
            polys[i] = std::move(u);
            polys.erase(polys.begin() + static_cast<long>(j));
            merged = true;
          }
      }
  }
  // Drop collinear vertices.
  for (auto& poly : polys) {
    std::vector<int> kept;
    for (size_t i = 0; i < poly.size(); ++i) {
      const Vec2& a = at[poly[(i + poly.size() - 1) % poly.size()]];
      const Vec2& b = at[poly[i]];
      const Vec2& c = at[poly[(i + 1) % poly.size()]];
      if (std::abs(cross2(b - a, c - b)) > 1e-12) kept.push_back(poly[i]);
    }
    poly = std::move(kept);
  }
  return polys;
}

}  // namespace

std::vector<std::vector<Eigen::Vector3d>> support_surfaces(const std::vector<Eigen::Vector3d>& vertices,
                                                           const std::vector<std::array<std::uint32_t, 3>>& triangles,
                                                           const Pose& world_T_mesh, const SupportSurfaceOptions& o) {
  // World coordinates; vertices that coincide (to 10 um) share one id.
  std::vector<Eigen::Vector3d> world;
  std::vector<int> id(vertices.size());
  std::map<std::array<long, 3>, int> ids;
  for (size_t i = 0; i < vertices.size(); ++i) {
    const Eigen::Vector3d w = world_T_mesh * vertices[i];
    const std::array<long, 3> key{std::lround(w.x() * 1e5), std::lround(w.y() * 1e5), std::lround(w.z() * 1e5)};
    auto [it, added] = ids.emplace(key, static_cast<int>(world.size()));
    if (added) world.push_back(w);
    id[i] = it->second;
  }
  // Upward triangles, and regions of them joined across shared vertices at the same height.
  std::vector<std::array<int, 3>> up;
  for (const auto& t : triangles) {
    const std::array<int, 3> v{id[t[0]], id[t[1]], id[t[2]]};
    const Eigen::Vector3d n = (world[v[1]] - world[v[0]]).cross(world[v[2]] - world[v[0]]);
    if (n.norm() <= 1e-14 || n.normalized().z() < std::cos(o.max_tilt)) continue;
    up.push_back(v);
  }
  std::vector<int> parent(up.size());
  std::iota(parent.begin(), parent.end(), 0);
  auto find = [&](int x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  };
  std::map<int, std::vector<int>> by_vertex;
  for (size_t k = 0; k < up.size(); ++k)
    for (int v : up[k]) by_vertex[v].push_back(static_cast<int>(k));
  auto height = [&](int k) { return (world[up[k][0]].z() + world[up[k][1]].z() + world[up[k][2]].z()) / 3; };
  for (const auto& [v, tris] : by_vertex)
    for (size_t a = 1; a < tris.size(); ++a)
      if (std::abs(height(tris[a]) - height(tris[0])) <= o.height_tolerance) parent[find(tris[a])] = find(tris[0]);
  std::map<int, std::vector<int>> regions;
  for (size_t k = 0; k < up.size(); ++k) regions[find(static_cast<int>(k))].push_back(static_cast<int>(k));

  struct Piece {
    double area;
    std::vector<Eigen::Vector3d> polygon;
  };
  std::vector<Piece> pieces;
  std::vector<Vec2> at(world.size());
  for (size_t i = 0; i < world.size(); ++i) at[i] = world[i].head<2>();
  const Pose mesh_T_world = world_T_mesh.inverse();
  for (const auto& [_, tris] : regions) {
    double area = 0.0, z = 0.0;
    std::vector<Vec2> points;
    std::vector<std::vector<int>> polys;
    for (int k : tris) {
      std::vector<Vec2> t{at[up[k][0]], at[up[k][1]], at[up[k][2]]};
      const double a = polygon_area(t);
      area += std::abs(a);
      z += height(k) * std::abs(a);
      for (int v : up[k]) points.push_back(at[v]);
      polys.push_back(a >= 0 ? std::vector<int>{up[k][0], up[k][1], up[k][2]} : std::vector<int>{up[k][0], up[k][2], up[k][1]});
    }
    if (area < o.min_area) continue;
    z /= area;
    auto lift = [&](const Vec2& p) { return Eigen::Vector3d(mesh_T_world * Eigen::Vector3d(p.x(), p.y(), z)); };
    std::vector<Vec2> hull;
    for (int i : hull_2d(points)) hull.push_back(points[i]);
    if (polygon_area(hull) <= area / 0.97) {  // fills its hull: one polygon
      Piece piece{area, {}};
      for (const auto& p : hull) piece.polygon.push_back(lift(p));
      pieces.push_back(std::move(piece));
      continue;
    }
    for (const auto& poly : convex_pieces(polys, at)) {
      std::vector<Vec2> flat;
      for (int v : poly) flat.push_back(at[v]);
      const double a = polygon_area(flat);
      if (poly.size() < 3 || a < o.min_area) continue;
      Piece piece{a, {}};
      for (const auto& p : flat) piece.polygon.push_back(lift(p));
      pieces.push_back(std::move(piece));
    }
  }
  std::stable_sort(pieces.begin(), pieces.end(), [](const Piece& a, const Piece& b) { return a.area > b.area; });
  std::vector<std::vector<Eigen::Vector3d>> out;
  for (auto& p : pieces) out.push_back(std::move(p.polygon));
  return out;
}

}  // namespace demoplan
