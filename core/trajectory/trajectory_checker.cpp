#include "core/trajectory/trajectory_checker.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace demoplan {

namespace {

std::string fmt(const char* f, double a, double b = 0, double c = 0) {
  char buf[200];
  std::snprintf(buf, sizeof buf, f, a, b, c);
  return buf;
}

double distance_to_segment(const Eigen::VectorXd& q, const Eigen::VectorXd& a, const Eigen::VectorXd& b) {
  const Eigen::VectorXd d = b - a;
  const double len2 = d.squaredNorm();
  const double s = len2 > 0 ? std::clamp((q - a).dot(d) / len2, 0.0, 1.0) : 0.0;
  return (q - a - s * d).norm();
}

}  // namespace

CheckReport check_trajectory(const std::vector<TrajectorySample>& samples, const Path& path,
                             const JointLimitSet& limits, const CheckOptions& o) {
  CheckReport r;
  auto fail = [&](const std::string& message) {
    r.ok = false;
    if (r.violations.size() < o.max_violations) r.violations.push_back(message);
  };
  const long nj = limits.size();
  if (samples.empty()) {
    fail("no samples");
    return r;
  }
  const double tol = 1 + o.relative_tolerance;

  for (size_t i = 0; i < samples.size(); ++i) {
    const TrajectorySample& s = samples[i];
    if (s.q.size() != nj || s.v.size() != nj || s.a.size() != nj) {
      fail("sample " + std::to_string(i) + " has the wrong number of joints");
      return r;
    }
    if (i > 0 && !(s.t > samples[i - 1].t)) fail(fmt("sample %.0f: time %.9g s does not increase", i, s.t));
    for (long j = 0; j < nj; ++j) {
      const std::string at = "sample " + std::to_string(i) + " (t = " + fmt("%.6f", s.t) + " s), " + limits.names[j];
      if (!(s.q[j] >= limits.lower[j] - 1e-9 && s.q[j] <= limits.upper[j] + 1e-9))
        fail(at + fmt(": position %.9g beyond [%.9g, %.9g]", s.q[j], limits.lower[j], limits.upper[j]));
      const double rv = std::abs(s.v[j]) / limits.velocity[j], ra = std::abs(s.a[j]) / limits.acceleration[j];
      r.peak_velocity_ratio = std::max(r.peak_velocity_ratio, rv);
      r.peak_acceleration_ratio = std::max(r.peak_acceleration_ratio, ra);
      if (!(rv <= tol)) fail(at + fmt(": velocity %.9g beyond %.9g", s.v[j], limits.velocity[j]));
      if (!(ra <= tol)) fail(at + fmt(": acceleration %.9g beyond %.9g", s.a[j], limits.acceleration[j]));
      if (i == 0) continue;
      const TrajectorySample& p = samples[i - 1];
      const double dt = s.t - p.t;
      if (!(dt > 0)) continue;
      const double jk = limits.jerk[j];
      const double rj = std::abs(s.a[j] - p.a[j]) / dt / jk;
      r.peak_jerk_ratio = std::max(r.peak_jerk_ratio, rj);
      if (o.check_jerk && !(rj <= tol)) fail(at + fmt(": jerk %.9g beyond %.9g", (s.a[j] - p.a[j]) / dt, jk));
      // Consistency: what the stored derivatives integrate to, against what the positions did.
      const double dq_err = std::abs(s.q[j] - p.q[j] - dt * (s.v[j] + p.v[j]) / 2);
      if (dq_err > jk * dt * dt * dt / 12 * tol + 1e-9)
        fail(at + fmt(": position moved %.9g but the velocities integrate to %.9g", s.q[j] - p.q[j],
                      dt * (s.v[j] + p.v[j]) / 2));
      const double dv_err = std::abs(s.v[j] - p.v[j] - dt * (s.a[j] + p.a[j]) / 2);
      if (dv_err > jk * dt * dt / 3 * tol + 1e-9)
        fail(at + fmt(": velocity changed %.9g but the accelerations integrate to %.9g", s.v[j] - p.v[j],
                      dt * (s.a[j] + p.a[j]) / 2));
    }
  }

  // The planner's waypoints, in order, each at some sample; rest at the ends and the actions.
  const auto& W = path.waypoints;
  bool closed = false;
  for (const auto& w : W)
    if (w.action != GripperAction::None) {
      closed = w.action == GripperAction::Release;
      break;
    }
  std::vector<std::pair<size_t, bool>> gripper_changes;  // (sample, closed after it)
  size_t from = 0;
  for (size_t k = 0; k < W.size(); ++k) {
    // The closest sample of the first run of samples within tolerance (slowing down into a
    // stop, several samples may be within it).
    long found = -1;
    double closest = o.waypoint_tolerance;
    for (size_t i = from; i < samples.size(); ++i) {
      const double d = (samples[i].q - W[k].q).cwiseAbs().maxCoeff();
      if (d <= closest) closest = d, found = static_cast<long>(i);
      else if (found >= 0 && d > o.waypoint_tolerance) break;
    }
    r.waypoint_samples.push_back(found);
    if (found < 0) {
      fail("waypoint " + std::to_string(k) + " is never reached" +
           (k > 0 ? " after waypoint " + std::to_string(k - 1) : std::string()));
      continue;
    }
    from = static_cast<size_t>(found);
    const bool must_rest = k == 0 || k + 1 == W.size() || W[k].action != GripperAction::None;
    if (must_rest && samples[from].v.cwiseAbs().maxCoeff() > o.rest_tolerance)
      fail("waypoint " + std::to_string(k) + fmt(" must be reached at rest; speed %.3g there",
                                                  samples[from].v.cwiseAbs().maxCoeff()));
    if (W[k].action != GripperAction::None) gripper_changes.push_back({from, W[k].action == GripperAction::Grasp});
  }
  if (r.waypoint_samples.front() != 0) fail("the first sample is not the first waypoint");
  if (r.waypoint_samples.back() >= 0 && r.waypoint_samples.back() + 1 != static_cast<long>(samples.size()))
    fail("the trajectory goes on after the last waypoint");

  // The gripper: closed exactly from each grasp waypoint to the next release waypoint.
  size_t next = 0;
  for (size_t i = 0; i < samples.size(); ++i) {
    while (next < gripper_changes.size() && gripper_changes[next].first <= i) closed = gripper_changes[next++].second;
    if (samples[i].gripper_closed != closed)
      fail("sample " + std::to_string(i) + fmt(" (t = %.6f s): gripper should be ", samples[i].t) +
           (closed ? "closed" : "open"));
  }

  // How far the samples stray from the straight segments.
  for (size_t k = 0; k + 1 < W.size(); ++k) {
    const long a = r.waypoint_samples[k], b = r.waypoint_samples[k + 1];
    if (a < 0 || b < 0) continue;
    for (long i = a; i <= b; ++i)
      r.max_path_deviation = std::max(r.max_path_deviation, distance_to_segment(samples[i].q, W[k].q, W[k + 1].q));
  }
  return r;
}

}  // namespace demoplan
