#include "core/trajectory/time_parameterization.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "core/error.h"
#include "core/trajectory/double_s.h"
#include "core/trajectory/trapezoid.h"

namespace demoplan {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kTiny = 1e-12;

struct Segment {
  double length = 0;
  Eigen::VectorXd u;   // unit direction
  DoubleSLimits line;  // limits along the segment, in units of its length
};

struct Corner {
  bool blend = false;
  Eigen::VectorXd w;         // velocity direction at the waypoint, per unit corner speed
  double before = 0, after = 0;  // blend lengths on the incoming and outgoing segment
  double piece_in = 0, piece_out = 0;  // blend piece durations at unit corner speed
  double max_speed = 0;
};

Segment make_segment(const Eigen::VectorXd& d, const Eigen::VectorXd& V, const Eigen::VectorXd& A,
                     const Eigen::VectorXd& J) {
  Segment s;
  s.length = d.norm();
  s.u = s.length > kTiny ? Eigen::VectorXd(d / s.length) : Eigen::VectorXd::Zero(d.size());
  s.line = {kInf, kInf, kInf};
  for (long j = 0; j < d.size(); ++j) {
    const double u = std::abs(s.u[j]);
    if (u == 0) continue;
    s.line.velocity = std::min(s.line.velocity, V[j] / u);
    s.line.acceleration = std::min(s.line.acceleration, A[j] / u);
    s.line.jerk = std::min(s.line.jerk, J[j] / u);
  }
  return s;
}

// Per joint, the smaller of the two directions where both move the same way, else 0: the joint
// then moves monotonically through the waypoint and never overshoots it.
Eigen::VectorXd monotone_direction(const Eigen::VectorXd& u1, const Eigen::VectorXd& u2) {
  Eigen::VectorXd w = Eigen::VectorXd::Zero(u1.size());
  for (long j = 0; j < u1.size(); ++j)
    if (u1[j] * u2[j] > 0) w[j] = std::copysign(std::min(std::abs(u1[j]), std::abs(u2[j])), u1[j]);
  return w;
}

// The longest duration for which the quintic from (q0, v0, a=0) to (q1, v1, a=0) keeps every joint
// monotone: for each joint, the end velocities (same sign as its displacement) may sum to at most
// twice its mean velocity.
double monotone_duration(const Eigen::VectorXd& dq, const Eigen::VectorXd& v0, const Eigen::VectorXd& v1) {
  double h = kInf;
  for (long j = 0; j < dq.size(); ++j) {
    const double speed = std::abs(v0[j]) + std::abs(v1[j]);
    if (speed > 0) h = std::min(h, 2 * std::abs(dq[j]) / speed);
  }
  return h;
}

// Peak of |value| / limit over a piece, sampled.
struct Peaks {
  double v = 0, a = 0, j = 0;
};
template <class StateAt>
Peaks peaks(StateAt state_at, const Eigen::VectorXd& V, const Eigen::VectorXd& A, const Eigen::VectorXd& J,
            int samples) {
  Peaks p;
  for (int i = 0; i <= samples; ++i) {
    const MotionState m = state_at(static_cast<double>(i) / samples);
    p.v = std::max(p.v, (m.v.cwiseAbs().array() / V.array()).maxCoeff());
    p.a = std::max(p.a, (m.a.cwiseAbs().array() / A.array()).maxCoeff());
    p.j = std::max(p.j, (m.jerk.cwiseAbs().array() / J.array()).maxCoeff());
  }
  return p;
}

// One blend piece at unit corner speed: its duration and the highest corner speed its peaks allow
// (velocity scales with the speed, acceleration with its square, jerk with its cube).
// The displacement dq is given rather than taken as a difference of positions: a joint that barely
// moves would otherwise round to a zero displacement with a nonzero end velocity.
std::pair<double, double> blend_piece(const Eigen::VectorXd& q0, const Eigen::VectorXd& dq, const Eigen::VectorXd& v0,
                                      const Eigen::VectorXd& v1, const Eigen::VectorXd& V, const Eigen::VectorXd& A,
                                      const Eigen::VectorXd& J) {
  const double h = monotone_duration(dq, v0, v1);
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(q0.size());
  const Knot from{q0, v0, zero}, to{q0 + dq, v1, zero};
  const Peaks p = peaks([&](double s) { return quintic_hermite(from, to, h, s); }, V, A, J, 64);
  const double speed = std::min({1 / p.v, 1 / std::sqrt(p.a), 1 / std::cbrt(p.j)});
  return {h, speed};
}

double run_length_of(const std::vector<Segment>& seg, const std::vector<Corner>& corner, size_t k) {
  return seg[k].length - (corner[k].blend ? corner[k].after : 0) - (corner[k + 1].blend ? corner[k + 1].before : 0);
}

// Corner speeds, limited by their blend pieces, then by forward and backward passes so that every
// straight run can join the speeds at its ends.
std::vector<double> corner_speeds(const std::vector<Segment>& seg, const std::vector<Corner>& corner) {
  const size_t n = corner.size();
  std::vector<double> speed(n, 0.0);
  for (size_t k = 0; k < n; ++k) speed[k] = corner[k].blend ? corner[k].max_speed : 0.0;
  for (size_t k = 0; k + 1 < n; ++k)
    if (corner[k + 1].blend && seg[k].length > kTiny)
      speed[k + 1] = std::min(speed[k + 1], double_s_reach(run_length_of(seg, corner, k), speed[k], seg[k].line));
  for (size_t k = n - 1; k-- > 0;)
    if (corner[k].blend && seg[k].length > kTiny)
      speed[k] = std::min(speed[k], double_s_reach(run_length_of(seg, corner, k), speed[k + 1], seg[k].line));
  return speed;
}

double total_duration(const std::vector<Segment>& seg, const std::vector<Corner>& corner,
                      const std::vector<double>& speed) {
  double t = 0;
  for (size_t k = 0; k < seg.size(); ++k)
    if (seg[k].length > kTiny) t += plan_double_s(run_length_of(seg, corner, k), speed[k], speed[k + 1], seg[k].line).duration();
  for (size_t k = 0; k < corner.size(); ++k)
    if (corner[k].blend) t += (corner[k].piece_in + corner[k].piece_out) / speed[k];
  return t;
}

}  // namespace

Trajectory time_parameterize(const Path& path, const JointLimitSet& limits, const TimingOptions& o) {
  check_path_within_limits(path, limits, o.source);
  if (path.waypoints.size() < 2) throw InputError(o.source, "waypoints", "a trajectory needs at least two waypoints");
  const auto& W = path.waypoints;
  const size_t n = W.size();
  const Eigen::VectorXd V = limits.velocity * o.limit_margin, A = limits.acceleration * o.limit_margin,
                        J = limits.jerk * o.limit_margin;

  std::vector<Segment> seg;
  for (size_t k = 0; k + 1 < n; ++k) seg.push_back(make_segment(W[k + 1].q - W[k].q, V, A, J));

  // Where the robot rests: ends, gripper actions, and around zero-length segments.
  std::vector<char> stop(n, 0);
  for (size_t k = 0; k < n; ++k)
    stop[k] = k == 0 || k + 1 == n || W[k].action != GripperAction::None || seg[k - 1].length <= kTiny ||
              seg[k].length <= kTiny;
  for (size_t k : o.rest_at)
    if (k < n) stop[k] = 1;
  if (!(o.blend_length > 0)) stop.assign(n, 1);  // no blends: rest at every waypoint

  // Blends at the other waypoints.
  std::vector<Corner> corner(n);
  for (size_t k = 1; k + 1 < n; ++k) {
    if (stop[k]) continue;
    Corner& c = corner[k];
    const Segment &in = seg[k - 1], &out = seg[k];
    c.w = monotone_direction(in.u, out.u);
    if (c.w.isZero()) {  // every joint turns back: rest there
      stop[k] = 1;
      continue;
    }
    c.blend = true;
    c.before = std::min(o.blend_length, in.length / 3);
    c.after = std::min(o.blend_length, out.length / 3);
    const auto [h_in, s_in] = blend_piece(W[k].q - c.before * in.u, c.before * in.u, in.u, c.w, V, A, J);
    const auto [h_out, s_out] = blend_piece(W[k].q, c.after * out.u, c.w, out.u, V, A, J);
    c.piece_in = h_in, c.piece_out = h_out;
    c.max_speed = std::min({s_in, s_out, in.line.velocity, out.line.velocity});
  }

  // A sharp corner only allows a low speed through its blend pieces, and crawling through them
  // can take longer than resting there: keep each blend only where it saves time.
  std::vector<double> speed = corner_speeds(seg, corner);
  double best = total_duration(seg, corner, speed);
  for (size_t k = 1; k + 1 < n; ++k) {
    if (!corner[k].blend) continue;
    corner[k].blend = false;
    const std::vector<double> trial = corner_speeds(seg, corner);
    const double d = total_duration(seg, corner, trial);
    if (d < best) {
      best = d, speed = trial, stop[k] = 1;
    } else {
      corner[k].blend = true;
    }
  }
  auto run_length = [&](size_t k) { return run_length_of(seg, corner, k); };

  // Knots: runs along the segments, blend pieces around the pass-through waypoints.
  Trajectory tr;
  tr.joint_names = path.joint_names;
  tr.actions.resize(n);
  tr.stops = stop;
  tr.waypoint_times.assign(n, 0.0);
  for (size_t k = 0; k < n; ++k) tr.actions[k] = W[k].action;
  for (const auto& w : W)
    if (w.action != GripperAction::None) {
      tr.starts_closed = w.action == GripperAction::Release;
      break;
    }
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(static_cast<long>(limits.names.size()));
  for (size_t k = 0; k + 1 < n; ++k) {
    const Segment& s = seg[k];
    const Corner &c0 = corner[k], &c1 = corner[k + 1];
    if (s.length > kTiny) {
      const Eigen::VectorXd r0 = c0.blend ? Eigen::VectorXd(W[k].q + c0.after * s.u) : W[k].q;
      const Eigen::VectorXd r1 = c1.blend ? Eigen::VectorXd(W[k + 1].q - c1.before * s.u) : W[k + 1].q;
      tr.motion.add_run(r0, r1, s.u, plan_double_s(run_length(k), speed[k], speed[k + 1], s.line));
    }
    if (c1.blend) {
      const double v = speed[k + 1];
      const Knot in{W[k + 1].q - c1.before * s.u, v * s.u, zero}, at{W[k + 1].q, v * c1.w, zero},
          out{W[k + 1].q + c1.after * seg[k + 1].u, v * seg[k + 1].u, zero};
      const double begin = tr.motion.duration();
      tr.motion.add_quintic(in, at, c1.piece_in / v);
      tr.waypoint_times[k + 1] = tr.motion.duration();
      tr.motion.add_quintic(at, out, c1.piece_out / v);
      tr.blends.push_back({k + 1, begin, tr.motion.duration()});
    } else {
      tr.waypoint_times[k + 1] = tr.motion.duration();
    }
  }
  if (tr.motion.pieces() == 0) throw InputError(o.source, "waypoints", "the path does not move");
  tr.duration = tr.motion.duration();

  // Final check of every piece against the true limits; a miss (the blend pieces are sized from
  // samples) slows the whole motion down uniformly, which scales every derivative down.
  double worst = 1.0;
  for (size_t i = 0; i < tr.motion.pieces(); ++i) {
    const Peaks p = peaks([&](double s) { return tr.motion.on_piece(i, s); }, limits.velocity, limits.acceleration,
                          limits.jerk, 32);
    worst = std::max({worst, p.v, std::sqrt(p.a), std::cbrt(p.j)});
  }
  if (worst > 1.0) {
    tr.safety_scale = worst * (1 + 1e-9);
    tr.motion.scale_time(tr.safety_scale);
    tr.duration = tr.motion.duration();
    for (double& wt : tr.waypoint_times) wt *= tr.safety_scale;
    for (auto& b : tr.blends) b.begin *= tr.safety_scale, b.end *= tr.safety_scale;
  }
  tr.trapezoid_duration = trapezoid_duration(path, limits);
  return tr;
}

}  // namespace demoplan
