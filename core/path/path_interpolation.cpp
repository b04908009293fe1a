#include "core/path/path_interpolation.h"

#include <algorithm>
#include <cmath>
#include <set>

#include "core/geometry/se3.h"
#include "core/model/kinematics.h"

namespace demoplan {

namespace {
bool same_pose(const Pose& a, const Pose& b, double tol) {
  return (a.matrix() - b.matrix()).cwiseAbs().maxCoeff() <= tol;
}
}  // namespace

PathInterpolator::PathInterpolator(const Scene& scene, const Path& path) : scene_(scene), path_(path) {
  const auto& wps = path.waypoints;
  cumulative_.push_back(0.0);
  for (size_t k = 1; k < wps.size(); ++k) cumulative_.push_back(cumulative_.back() + (wps[k].q - wps[k - 1].q).norm());
  total_ = cumulative_.back();
  const RobotModel& model = scene.robot.model;
  PoseVector la, lb;
  for (size_t k = 0; k + 1 < wps.size(); ++k) {
    forward_kinematics(model, wps[k].q, scene.robot.base, la);
    forward_kinematics(model, wps[k + 1].q, scene.robot.base, lb);
    std::vector<ObjectMotion> row(wps[k].objects.size());
    for (size_t o = 0; o < row.size(); ++o) {
      const Pose& a = wps[k].objects[o];
      const Pose& b = wps[k + 1].objects[o];
      if (same_pose(a, b, 1e-9)) continue;
      bool carried = false;
      for (size_t l = 0; l < model.links.size() && !carried; ++l) {
        const Pose ra = la[l].inverse() * a, rb = lb[l].inverse() * b;
        if (same_pose(ra, rb, 1e-6)) row[o] = {static_cast<int>(l), ra}, carried = true;
      }
      if (!carried) uncarried_.emplace_back(static_cast<int>(k), static_cast<int>(o));
    }
    motion_.push_back(std::move(row));
  }
}

SceneState PathInterpolator::at(double t) const {
  const auto& wps = path_.waypoints;
  SceneState s;
  if (wps.size() == 1 || total_ <= 0.0) {
    s.q = wps.front().q;
    s.objects = wps.front().objects;
    return s;
  }
  const double d = std::clamp(t, 0.0, 1.0) * total_;
  size_t k = std::upper_bound(cumulative_.begin(), cumulative_.end(), d) - cumulative_.begin();
  k = std::clamp<size_t>(k, 1, wps.size() - 1) - 1;  // segment k: waypoints k, k+1
  const double span = cumulative_[k + 1] - cumulative_[k];
  const double u = span > 0 ? (d - cumulative_[k]) / span : 1.0;
  return on_segment(k, (1 - u) * wps[k].q + u * wps[k + 1].q, u);
}

SceneState PathInterpolator::on_segment(size_t k, const Eigen::VectorXd& q, double u) const {
  const auto& wps = path_.waypoints;
  SceneState s;
  s.q = q;
  s.objects = wps[k].objects;
  PoseVector links;
  bool have_links = false;
  for (size_t o = 0; o < s.objects.size(); ++o) {
    const ObjectMotion& m = motion_[k][o];
    const Pose& a = wps[k].objects[o];
    const Pose& b = wps[k + 1].objects[o];
    if (m.link >= 0) {
      if (!have_links) forward_kinematics(scene_.robot.model, s.q, scene_.robot.base, links), have_links = true;
      s.objects[o] = links[m.link] * m.link_T_object;
    } else if (!(a.matrix() == b.matrix())) {
      // Uncarried: interpolate, so a validator sees it move.
      s.objects[o] = interpolate(a, b, u);
    }
  }
  return s;
}

std::vector<double> PathInterpolator::sample_parameters(double delta, double max_step) const {
  std::set<double> ts;
  const int n = static_cast<int>(std::ceil((1.0 + delta) / delta));
  for (int k = 0; k < n; ++k) ts.insert(std::min(1.0, k * delta));
  if (total_ > 0) {
    for (size_t k = 0; k + 1 < path_.waypoints.size(); ++k) {
      const double a = waypoint_parameter(k), b = waypoint_parameter(k + 1);
      const int steps = static_cast<int>(std::ceil((b - a) * total_ / max_step));
      for (int i = 0; i <= steps; ++i) ts.insert(a + (b - a) * i / std::max(steps, 1));
    }
  }
  return {ts.begin(), ts.end()};
}

}  // namespace demoplan
