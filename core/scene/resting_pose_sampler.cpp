#include "core/scene/resting_pose_sampler.h"

#include <Eigen/Geometry>
#include <cmath>

namespace demoplan {

RestingPoseSampler::RestingPoseSampler(const Scene& scene, PlacementTolerance tolerance)
    : scene_(scene), tolerance_(tolerance) {
  for (auto& p : support_polygons(scene)) {
    if (p.furniture < 0 || p.vertices.size() < 3) continue;  // robot surfaces move with the robot
    Support s;
    s.plane = polygon_plane(p.vertices);
    if (s.plane.normal.z() < 0.7) continue;  // a wall or a ceiling: nothing rests on it
    s.lo = s.hi = Eigen::Vector2d::Zero();
    for (const auto& v : p.vertices) {
      const Eigen::Vector3d d = v - s.plane.origin;
      s.corners.emplace_back(d.dot(s.plane.u), d.dot(s.plane.v));
      s.lo = s.lo.cwiseMin(s.corners.back());
      s.hi = s.hi.cwiseMax(s.corners.back());
    }
    for (size_t i = 0; i < s.corners.size(); ++i) {
      const Eigen::Vector2d& a = s.corners[i];
      const Eigen::Vector2d& b = s.corners[(i + 1) % s.corners.size()];
      s.area += 0.5 * (a.x() * b.y() - a.y() * b.x());
    }
    s.area = std::abs(s.area);
    polygons_.push_back(std::move(p));
    supports_.push_back(std::move(s));
  }
  for (const auto& object : scene.objects) {
    std::vector<Face> faces;
    for (const auto& poly : object_contact_polygons(object)) {
      if (poly.size() < 3) continue;
      const PolygonPlane plane = polygon_plane(poly);
      Face f{plane.origin, plane.normal};
      // The object's origin (the centre of a BOP model) lies inside it, behind the face.
      if ((Eigen::Vector3d::Zero() - f.origin).dot(f.normal) > 0.0) f.normal = -f.normal;
      faces.push_back(f);
    }
    faces_.push_back(std::move(faces));
  }
}

std::optional<Pose> RestingPoseSampler::sample(int object, std::mt19937_64& rng, int attempts) const {
  const auto& faces = faces_[static_cast<size_t>(object)];
  if (supports_.empty() || faces.empty()) return std::nullopt;
  std::vector<double> areas;
  for (const auto& s : supports_) areas.push_back(s.area);
  std::discrete_distribution<size_t> pick_support(areas.begin(), areas.end());
  std::uniform_int_distribution<size_t> pick_face(0, faces.size() - 1);
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  // Halfway through the benchmark's slab above the support.
  const double lift = 0.5 * (tolerance_.lower + tolerance_.upper);
  for (int a = 0; a < attempts; ++a) {
    const Support& s = supports_[pick_support(rng)];
    const Face& f = faces[pick_face(rng)];
    Eigen::Vector2d p;
    bool inside = false;
    for (int k = 0; k < 50 && !inside; ++k) {
      p = s.lo + (s.hi - s.lo).cwiseProduct(Eigen::Vector2d(u01(rng), u01(rng)));
      inside = true;
      for (size_t i = 0; i < s.corners.size() && inside; ++i) {
        const Eigen::Vector2d e = s.corners[(i + 1) % s.corners.size()] - s.corners[i];
        const Eigen::Vector2d r = p - s.corners[i];
        inside = e.x() * r.y() - e.y() * r.x() >= 0.0;
      }
    }
    if (!inside) continue;
    // The face's outward normal onto the support's downward normal, then a free turn about it.
    const Eigen::Matrix3d align = Eigen::Quaterniond::FromTwoVectors(f.normal, -s.plane.normal).toRotationMatrix();
    const Eigen::Matrix3d turn = Eigen::AngleAxisd(2.0 * M_PI * u01(rng), s.plane.normal).toRotationMatrix();
    Pose pose = Pose::Identity();
    pose.linear() = turn * align;
    const Eigen::Vector3d target = s.plane.origin + p.x() * s.plane.u + p.y() * s.plane.v + lift * s.plane.normal;
    pose.translation() = target - pose.linear() * f.origin;
    if (check_placement(scene_, polygons_, {}, object, pose, tolerance_).placed) return pose;
  }
  return std::nullopt;
}

}  // namespace demoplan
