#include "core/demo/rest_pose.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/statistics.h"

namespace demoplan {

Pose robust_static_pose(const PoseList& samples, double inlier_angle) {
  const size_t n = samples.size();
  Pose out = Pose::Identity();
  if (n == 0) return out;
  for (int k = 0; k < 3; ++k) {
    std::vector<double> v;
    for (const auto& s : samples) v.push_back(s.translation()[k]);
    out.translation()[k] = order_statistic(std::move(v), n / 2);
  }
  std::vector<Eigen::Quaterniond> q;
  for (const auto& s : samples) q.emplace_back(Eigen::Quaterniond(s.linear()).normalized());
  size_t medoid = 0;
  double best = std::numeric_limits<double>::infinity();
  for (size_t i = 0; i < n; ++i) {
    double sum = 0;
    for (size_t j = 0; j < n; ++j) sum += q[i].angularDistance(q[j]);
    if (sum < best) best = sum, medoid = i;
  }
  Eigen::Vector4d acc = Eigen::Vector4d::Zero();
  for (size_t i = 0; i < n; ++i) {
    if (q[medoid].angularDistance(q[i]) > inlier_angle) continue;
    const double sign = q[medoid].dot(q[i]) < 0 ? -1.0 : 1.0;  // same hemisphere
    acc += sign * q[i].coeffs();
  }
  out.linear() = Eigen::Quaterniond(acc.normalized()).toRotationMatrix();
  return out;
}

namespace {
Eigen::Vector3d centroid(const std::vector<Eigen::Vector3d>& pts) {
  Eigen::Vector3d c = Eigen::Vector3d::Zero();
  for (const auto& p : pts) c += p;
  return c / static_cast<double>(pts.size());
}

// In-plane vector that moves `point` inside the polygon, 1 cm past the nearest edge (zero when
// it is inside already).
Eigen::Vector3d slide_inside(const PolygonPlane& plane, const std::vector<Eigen::Vector3d>& poly,
                             const Eigen::Vector3d& point) {
  if (projects_inside(plane, poly, point)) return Eigen::Vector3d::Zero();
  const Eigen::Vector3d p = point - (point - plane.origin).dot(plane.normal) * plane.normal;
  Eigen::Vector3d nearest = poly[0];
  double best = std::numeric_limits<double>::infinity();
  for (size_t i = 0; i < poly.size(); ++i) {
    const Eigen::Vector3d a = poly[i], b = poly[(i + 1) % poly.size()];
    const double t = std::clamp((p - a).dot(b - a) / (b - a).squaredNorm(), 0.0, 1.0);
    const Eigen::Vector3d c = a + t * (b - a);
    if ((c - p).norm() < best) best = (c - p).norm(), nearest = c;
  }
  const Eigen::Vector3d inward = (centroid(poly) - nearest).normalized();
  return nearest + 0.01 * inward - p;
}
}  // namespace

std::optional<SnapResult> snap_to_support(const std::vector<std::vector<Eigen::Vector3d>>& faces,
                                          const Pose& pose,
                                          const std::vector<std::vector<Eigen::Vector3d>>& supports,
                                          const SnapOptions& options) {
  // The object is levelled about its middle (the centroid of its contact polygons), not about
  // the face it lands on: an estimate's tilt is an error of its orientation about the part's
  // middle, whose position is estimated best. About the face, a tall part's 11-degree tilt
  // (waiter_0's sugar box on the shelf) moves it 15 mm sideways.
  std::vector<Eigen::Vector3d> all;
  for (const auto& f : faces) all.insert(all.end(), f.begin(), f.end());
  if (all.empty()) return std::nullopt;
  const Eigen::Vector3d middle = pose * centroid(all);
  std::optional<SnapResult> best;
  double best_score = std::numeric_limits<double>::infinity();
  for (size_t s = 0; s < supports.size(); ++s) {
    const PolygonPlane plane = polygon_plane(supports[s]);
    for (size_t f = 0; f < faces.size(); ++f) {
      std::vector<Eigen::Vector3d> w;
      for (const auto& v : faces[f]) w.push_back(pose * v);
      // The face rests on the support when its outward normal points against the support's.
      const Eigen::Vector3d face_normal = polygon_plane(w).normal;
      const double tilt = std::acos(std::clamp(-face_normal.dot(plane.normal), -1.0, 1.0));
      if (tilt > options.max_tilt) continue;
      const Eigen::Matrix3d align =
          Eigen::Quaterniond::FromTwoVectors(face_normal, -plane.normal).toRotationMatrix();
      Pose corrected = pose;
      corrected.linear() = align * pose.linear();
      corrected.translation() = middle + align * (pose.translation() - middle);
      const Eigen::Vector3d c = corrected * centroid(faces[f]);
      const double distance = (c - plane.origin).dot(plane.normal);
      if (std::abs(distance) > options.max_distance) continue;
      Eigen::Vector3d along = plane.normal;  // the height is set moving this way
      if (options.viewpoint) {
        const Eigen::Vector3d sight = (middle - *options.viewpoint).normalized();
        if (std::abs(sight.dot(plane.normal)) > std::sin(10.0 * M_PI / 180)) along = sight / sight.dot(plane.normal);
      }
      const Eigen::Vector3d lift = (options.gap - distance) * along;
      const Eigen::Vector3d slide = slide_inside(plane, supports[s], c + lift);
      if (slide.norm() > options.max_outside) continue;
      // 1 cm off the plane or outside the polygon weighs like 0.1 rad of tilt.
      const double score = tilt + (std::abs(distance) + slide.norm()) * 10.0;
      if (score >= best_score) continue;
      best_score = score;
      corrected.translation() += lift + slide;
      best = SnapResult{corrected, static_cast<int>(s), static_cast<int>(f), tilt, options.gap - distance, slide.norm()};
    }
  }
  return best;
}

}  // namespace demoplan
