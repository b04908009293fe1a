#include "core/demo/supported_rests.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/demo/settle_demonstration.h"
#include "core/error.h"
#include "core/model/kinematics.h"
#include "core/scene/support.h"

namespace demoplan {

namespace {

std::string millimetres(double metres) { return std::to_string(std::lround(std::abs(metres) * 1000.0)) + " mm"; }

Eigen::Vector3d centroid(const std::vector<Eigen::Vector3d>& points) {
  Eigen::Vector3d c = Eigen::Vector3d::Zero();
  for (const auto& p : points) c += p;
  return c / static_cast<double>(points.size());
}

// Why `object` at `pose` is not placed, in the user's terms: how far its resting face is from the
// support under it (the nearest, among those a face of it looks down on), or that none is under it.
std::string why_unsupported(const Scene& scene, const std::vector<SupportPolygon>& supports,
                            const std::vector<std::vector<Eigen::Vector3d>>& world_supports, int object,
                            const Pose& pose, const PlacementTolerance& tol) {
  const double max_tilt = 0.35;  // rad: a face tilted further does not rest on that support
  const auto faces = object_contact_polygons(scene.objects[static_cast<size_t>(object)]);
  struct Nearest {
    int support = -1;
    double low = 0, high = 0, tilt = 0;
    bool overhangs = false;
  } best;
  double best_gap = std::numeric_limits<double>::infinity();
  for (size_t s = 0; s < world_supports.size(); ++s) {
    const PolygonPlane plane = polygon_plane(world_supports[s]);
    for (const auto& face : faces) {
      std::vector<Eigen::Vector3d> w;
      for (const auto& v : face) w.push_back(pose * v);
      const double tilt = std::acos(std::clamp(-polygon_plane(w).normal.dot(plane.normal), -1.0, 1.0));
      if (tilt > max_tilt || !projects_inside(plane, world_supports[s], centroid(w))) continue;
      Nearest n{static_cast<int>(s), std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity(),
                tilt, false};
      for (const auto& x : w) {
        const double h = (x - plane.origin).dot(plane.normal);
        n.low = std::min(n.low, h), n.high = std::max(n.high, h);
        n.overhangs |= !projects_inside(plane, world_supports[s], x);
      }
      if (std::abs(n.low) < best_gap) best_gap = std::abs(n.low), best = n;
    }
  }
  const std::string part = scene.objects[static_cast<size_t>(object)].id + " rests on no support: ";
  const std::string fix = "; move it onto a support";
  if (best.support < 0) {
    // Not over any support: name the closest one to move it to.
    int nearest = -1;
    double d = std::numeric_limits<double>::infinity();
    for (size_t s = 0; s < world_supports.size(); ++s)
      if (const double ds = (centroid(world_supports[s]) - pose.translation()).norm(); ds < d) d = ds, nearest = static_cast<int>(s);
    return part + "it is over none" + (nearest >= 0 ? " (the nearest is " + supports[static_cast<size_t>(nearest)].name + ")" : "") + fix;
  }
  const std::string name = supports[static_cast<size_t>(best.support)].name;
  const std::string tilted = best.tilt > 0.017 ? ", tilted " + std::to_string(std::lround(best.tilt * 180 / M_PI)) + " degrees" : "";
  if (best.low >= tol.upper) return part + millimetres(best.low) + " above the nearest (" + name + ")" + tilted + fix;
  if (best.low <= tol.lower) return part + millimetres(best.low) + " into the nearest (" + name + ")" + tilted + fix;
  if (best.overhangs) return part + "it hangs over the edge of " + name + fix;
  return part + "tilted " + std::to_string(std::lround(best.tilt * 180 / M_PI)) + " degrees on " + name + fix;
}

}  // namespace

std::vector<UnsupportedRest> unsupported_rests(const Scene& scene, const Demonstration& demo) {
  std::vector<UnsupportedRest> out;
  if (!validate(demo).empty() || demo.object_ids.size() != scene.objects.size()) return out;
  const std::vector<SupportPolygon> supports = support_polygons(scene);
  if (supports.empty()) return out;  // nothing to rest on at all: the cell says so when it loads
  PoseVector links;
  forward_kinematics(scene.robot.model, scene.robot.initial_configuration, scene.robot.base, links);
  std::vector<std::vector<Eigen::Vector3d>> world = {};
  for (const auto& s : supports) {
    world.push_back(s.vertices);
    if (s.robot_link >= 0)
      for (auto& v : world.back()) v = links[static_cast<size_t>(s.robot_link)] * v;
  }
  const PlacementTolerance tol;  // the validator's
  auto check = [&](int event, int object) {
    const ContactEvent& e = demo.events[static_cast<size_t>(event)];
    if (!e.pose_frame(object).empty()) return;
    const Pose& pose = e.poses[static_cast<size_t>(object)];
    if (check_placement(scene, supports, links, object, pose, tol).placed) return;
    out.push_back({event, e.frame, object, why_unsupported(scene, supports, world, object, pose, tol)});
  };
  // As build_constraint_graph takes the rests: the first grasp (or first event), then releases.
  for (size_t o = 0; o < demo.object_ids.size(); ++o) {
    int first = 0;
    for (size_t i = 0; i < demo.events.size(); ++i)
      if (demo.events[i].object == static_cast<int>(o) && demo.events[i].type == EventType::Grasp) {
        first = static_cast<int>(i);
        break;
      }
    check(first, static_cast<int>(o));
  }
  for (size_t i = 0; i < demo.events.size(); ++i)
    if (demo.events[i].type == EventType::Release) check(static_cast<int>(i), demo.events[i].object);
  std::sort(out.begin(), out.end(), [](const UnsupportedRest& a, const UnsupportedRest& b) {
    return a.event != b.event ? a.event < b.event : a.object < b.object;
  });
  return out;
}

Demonstration settle_for_planning(const Scene& scene, Demonstration demo, const std::string& source) {
  demo = settle_on_supports(scene, std::move(demo));
  if (const auto rests = unsupported_rests(scene, demo); !rests.empty()) {
    const UnsupportedRest& r = rests.front();
    throw InputError(source, "events[" + std::to_string(r.event) + "] (frame " + std::to_string(r.frame) + ")", r.message);
  }
  return demo;
}

}  // namespace demoplan
