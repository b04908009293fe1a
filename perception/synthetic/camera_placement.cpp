#include "perception/synthetic/camera_placement.h"

#include <cmath>
#include <limits>

#include "core/geometry/ray_box.h"
#include "perception/camera/look_at.h"

namespace demoplan::perception {

bool segment_hits_box(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::AlignedBox3d& box) {
  // The last 5 cm before `b` do not count: the point itself may lie on the box.
  const Eigen::Vector3d d = b - a;
  return ray_hits_box(a, d, box, 0.0, 1 - 0.05 / std::max(d.norm(), 0.06));
}

Camera place_camera(const DemoScript& s, const std::vector<Eigen::AlignedBox3d>& obstacles,
                    const std::vector<std::vector<ObjectMarker>>& markers, const CameraPlacementOptions& o,
                    CameraPlacementReport* report) {
  // The points to keep in view: every part's box corners along the video (every 3rd frame).
  std::vector<Eigen::Vector3d> points, rest_centres;
  for (int f = 0; f < s.frames; f += 3)
    for (size_t k = 0; k < s.object_ids.size(); ++k)
      for (int c = 0; c < 8; ++c)
        points.push_back(s.poses[f][k] * s.bounds[k].corner(static_cast<Eigen::AlignedBox3d::CornerType>(c)));
  points.insert(points.end(), o.also_in_view.begin(), o.also_in_view.end());
  std::vector<int> rest_frames{0};
  for (const auto& c : s.carries) rest_frames.push_back(c.release);
  // Where each resting part's markers are: centre and normal in the world.
  struct MarkerView {
    Eigen::Vector3d centre, normal;
    std::vector<Eigen::Vector3d> points;  // centre and corners
  };
  struct Rest {
    std::vector<MarkerView> markers;
  };
  std::vector<Rest> rests;
  for (int f : rest_frames)
    for (size_t k = 0; k < s.object_ids.size() && k < markers.size(); ++k) {
      Rest r;
      for (const auto& m : markers[k]) {
        const Pose T = s.poses[f][k] * m.object_T_marker;
        MarkerView v{T.translation(), T.linear().col(2), {T.translation()}};
        for (int c = 0; c < 4; ++c)
          v.points.push_back(T * Eigen::Vector3d(c & 1 ? m.size / 2 : -m.size / 2, c & 2 ? m.size / 2 : -m.size / 2, 0));
        r.markers.push_back(v);
      }
      rests.push_back(r);
    }
  for (int f : rest_frames)
    for (size_t k = 0; k < s.object_ids.size(); ++k) {
      // The centre and the corners pulled in a little (corners on the support are hidden anyway).
      const Eigen::Vector3d c = s.bounds[k].center();
      rest_centres.push_back(s.poses[f][k] * c);
      for (int i = 0; i < 8; ++i)
        rest_centres.push_back(s.poses[f][k] * (c + 0.8 * (s.bounds[k].corner(static_cast<Eigen::AlignedBox3d::CornerType>(i)) - c)));
    }
  Eigen::AlignedBox3d all;
  for (const auto& p : points) all.extend(p);
  const Eigen::Vector3d target = all.center();

  Camera best;
  best.image_size = o.image_size;
  best.fx = best.fy = o.fx;
  best.cx = (o.image_size.width - 1) / 2.0;
  best.cy = (o.image_size.height - 1) / 2.0;
  double best_score = std::numeric_limits<double>::infinity();
  // Until a view fits: nothing seen.
  if (report) *report = {markers.empty() ? 0 : static_cast<int>(rests.size()), static_cast<int>(rest_centres.size())};
  for (int a = 0; a < o.azimuths * static_cast<int>(o.elevations.size()); ++a) {
    const double az = 2 * M_PI * (a % o.azimuths) / o.azimuths;
    const double el = o.elevations[a / o.azimuths];
    const Eigen::Vector3d dir(std::cos(el) * std::cos(az), std::cos(el) * std::sin(az), std::sin(el));
    // The closest distance at which everything fits.
    double distance = -1;
    for (double d = 0.8; d < 8.0; d += 0.05) {
      const Pose T = look_at(target + d * dir, target);
      const Pose inv = T.inverse();
      bool fits = true;
      for (const auto& p : points) {
        const Eigen::Vector3d q = inv * p;
        const double u = o.fx * q.x() / q.z() + best.cx, v = o.fx * q.y() / q.z() + best.cy;
        if (q.z() < 0.3 || u < o.margin_px || v < o.margin_px || u > o.image_size.width - o.margin_px ||
            v > o.image_size.height - o.margin_px) {
          fits = false;
          break;
        }
      }
      if (fits) {
        distance = d;
        break;
      }
    }
    if (distance < 0) continue;
    const Eigen::Vector3d eye = target + distance * dir;
    int hidden = 0;
    for (const auto& c : rest_centres)
      for (const auto& box : obstacles)
        if (!box.contains(c) && segment_hits_box(eye, c, box)) {
          ++hidden;
          break;
        }
    int blind = 0;  // resting parts that show no marker
    for (const auto& r : rests) {
      bool seen = false;
      for (const auto& m : r.markers) {
        if (m.normal.dot((eye - m.centre).normalized()) < 0.34) continue;
        bool free = true;
        for (const auto& p : m.points)
          for (const auto& box : obstacles) free = free && (box.contains(p) || !segment_hits_box(eye, p, box));
        if (free) {
          seen = true;
          break;
        }
      }
      blind += !seen;
    }
    // A hidden point costs as much as 10 cm farther, a part without a visible marker 10 m.
    const double score = blind * 10.0 + hidden * 0.1 + distance;
    if (score < best_score) {
      best_score = score;
      best.world_T_camera = look_at(eye, target);
      if (report) *report = {blind, hidden};
    }
  }
  if (!best.world_T_camera) best.world_T_camera = look_at(target + 4.0 * Eigen::Vector3d(0, -0.7, 0.7), target);
  return best;
}

}  // namespace demoplan::perception
