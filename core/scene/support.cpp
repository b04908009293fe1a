#include "core/scene/support.h"

namespace demoplan {

std::vector<SupportPolygon> support_polygons(const Scene& scene) {
  std::vector<SupportPolygon> out;
  for (size_t f = 0; f < scene.furniture.size(); ++f) {
    const auto& fu = scene.furniture[f];
    for (const auto& c : fu.srdf.contacts) {
      const int link = fu.model.link_index(c.link);
      if (link < 0) continue;
      for (auto& poly : c.polygon_vertices()) {
        for (auto& v : poly) v = fu.link_poses[link] * v;  // furniture is fixed: store in world
        out.push_back({fu.name + "/" + c.name, static_cast<int>(f), -1, std::move(poly)});
      }
    }
  }
  const auto& robot = scene.robot;
  for (const auto& c : robot.srdf.contacts) {
    const int link = robot.model.link_index(c.link);
    if (link < 0) continue;
    for (auto& poly : c.polygon_vertices()) out.push_back({"robot/" + c.name, -1, link, std::move(poly)});
  }
  return out;
}

std::vector<std::vector<Eigen::Vector3d>> furniture_support_polygons(const Scene& scene) {
  std::vector<std::vector<Eigen::Vector3d>> out;
  for (const auto& s : support_polygons(scene))
    if (s.robot_link < 0) out.push_back(s.vertices);
  return out;
}

PolygonPlane polygon_plane(const std::vector<Eigen::Vector3d>& w) {
  PolygonPlane p;
  p.origin = w[0];
  Eigen::Vector3d best = Eigen::Vector3d::Zero();
  for (size_t i = 1; i < w.size(); ++i)
    for (size_t j = i + 1; j < w.size(); ++j) {
      const Eigen::Vector3d c = (w[i] - w[0]).cross(w[j] - w[0]);
      if (c.norm() > best.norm()) best = c;
    }
  p.normal = best.normalized();
  p.u = (w[1] - w[0]).normalized();
  p.u = (p.u - p.u.dot(p.normal) * p.normal).normalized();
  p.v = p.normal.cross(p.u);
  return p;
}

bool projects_inside(const PolygonPlane& plane, const std::vector<Eigen::Vector3d>& poly,
                     const Eigen::Vector3d& point, double tol) {
  auto to2d = [&](const Eigen::Vector3d& x) {
    const Eigen::Vector3d d = x - plane.origin;
    return Eigen::Vector2d(d.dot(plane.u), d.dot(plane.v));
  };
  const Eigen::Vector2d p = to2d(point);
  for (size_t i = 0; i < poly.size(); ++i) {
    const Eigen::Vector2d a = to2d(poly[i]), b = to2d(poly[(i + 1) % poly.size()]);
    const Eigen::Vector2d e = b - a, r = p - a;
    if (e.x() * r.y() - e.y() * r.x() < -tol) return false;  // right of an edge: outside
  }
  return true;
}

std::vector<std::vector<Eigen::Vector3d>> object_contact_polygons(const SceneObject& object) {
  std::vector<std::vector<Eigen::Vector3d>> out;
  PoseVector links;
  forward_kinematics(object.model, Eigen::VectorXd::Zero(object.model.nq), Pose::Identity(), links);
  for (const auto& c : object.srdf.contacts) {
    const int link = object.model.link_index(c.link);
    if (link < 0) continue;
    for (auto& poly : c.polygon_vertices()) {
      for (auto& v : poly) v = links[link] * v;
      out.push_back(std::move(poly));
    }
  }
  return out;
}

PlacementCheck check_placement(const Scene& scene, const std::vector<SupportPolygon>& supports,
                                const PoseVector& robot_link_poses, int object, const Pose& pose,
                                const PlacementTolerance& tol) {
  const auto faces = object_contact_polygons(scene.objects[object]);
  std::vector<Eigen::Vector3d> world;
  for (size_t s = 0; s < supports.size(); ++s) {
    world = supports[s].vertices;
    if (supports[s].robot_link >= 0)
      for (auto& v : world) v = robot_link_poses[supports[s].robot_link] * v;
    const PolygonPlane plane = polygon_plane(world);
    for (size_t f = 0; f < faces.size(); ++f) {
      bool ok = true;
      for (const auto& local : faces[f]) {
        const Eigen::Vector3d x = pose * local;
        const double h = (x - plane.origin).dot(plane.normal);
        if (!(h > tol.lower && h < tol.upper) || !projects_inside(plane, world, x)) {
          ok = false;
          break;
        }
      }
      if (ok) return {true, static_cast<int>(s), static_cast<int>(f)};
    }
  }
  return {};
}

}  // namespace demoplan
