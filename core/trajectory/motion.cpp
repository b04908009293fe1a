#include "core/trajectory/motion.h"

#include <algorithm>
#include <stdexcept>

namespace demoplan {

MotionState quintic_hermite(const Knot& k0, const Knot& k1, double h, double s) {
  // Hermite basis on s in [0, 1] with the derivatives scaled to the piece's duration h.
  const double s2 = s * s, s3 = s2 * s, s4 = s3 * s, s5 = s4 * s;
  const double h01 = 10 * s3 - 15 * s4 + 6 * s5;
  const double h10 = s - 6 * s3 + 8 * s4 - 3 * s5, h11 = -4 * s3 + 7 * s4 - 3 * s5;
  const double h20 = 0.5 * (s2 - 3 * s3 + 3 * s4 - s5), h21 = 0.5 * (s3 - 2 * s4 + s5);
  // Their first, second and third derivatives with respect to s.
  const double d01 = 30 * s2 - 60 * s3 + 30 * s4;
  const double d10 = 1 - 18 * s2 + 32 * s3 - 15 * s4, d11 = -12 * s2 + 28 * s3 - 15 * s4;
  const double d20 = 0.5 * (2 * s - 9 * s2 + 12 * s3 - 5 * s4), d21 = 0.5 * (3 * s2 - 8 * s3 + 5 * s4);
  const double e01 = 60 * s - 180 * s2 + 120 * s3;
  const double e10 = -36 * s + 96 * s2 - 60 * s3, e11 = -24 * s + 84 * s2 - 60 * s3;
  const double e20 = 0.5 * (2 - 18 * s + 36 * s2 - 20 * s3), e21 = 0.5 * (6 * s - 24 * s2 + 20 * s3);
  const double f01 = 60 - 360 * s + 360 * s2;
  const double f10 = -36 + 192 * s - 180 * s2, f11 = -24 + 168 * s - 180 * s2;
  const double f20 = 0.5 * (-18 + 72 * s - 60 * s2), f21 = 0.5 * (6 - 48 * s + 60 * s2);
  const Eigen::VectorXd dq = k1.q - k0.q;
  const Eigen::VectorXd V0 = h * k0.v, V1 = h * k1.v, A0 = h * h * k0.a, A1 = h * h * k1.a;
  MotionState m;
  m.q = s == 0 ? k0.q : s == 1 ? k1.q : Eigen::VectorXd(k0.q + h01 * dq + h10 * V0 + h11 * V1 + h20 * A0 + h21 * A1);
  m.v = (d01 * dq + d10 * V0 + d11 * V1 + d20 * A0 + d21 * A1) / h;
  m.a = (e01 * dq + e10 * V0 + e11 * V1 + e20 * A0 + e21 * A1) / (h * h);
  m.jerk = (f01 * dq + f10 * V0 + f11 * V1 + f20 * A0 + f21 * A1) / (h * h * h);
  return m;
}

void Motion::add_run(const Eigen::VectorXd& start, const Eigen::VectorXd& end, const Eigen::VectorXd& direction,
                     const DoubleS& profile) {
  Piece p;
  p.run = true;
  p.start = start, p.end = end, p.direction = direction, p.profile = profile;
  starts_.push_back(starts_.empty() ? 0.0 : starts_.back() + durations_.back());
  durations_.push_back(profile.duration());
  pieces_.push_back(std::move(p));
}

void Motion::add_quintic(const Knot& from, const Knot& to, double duration) {
  if (!(duration > 0)) throw std::invalid_argument("Motion::add_quintic: duration must be > 0");
  Piece p;
  p.from = from, p.to = to;
  starts_.push_back(starts_.empty() ? 0.0 : starts_.back() + durations_.back());
  durations_.push_back(duration);
  pieces_.push_back(std::move(p));
}

MotionState Motion::on_piece(size_t i, double s) const {
  const Piece& p = pieces_[i];
  s = std::clamp(s, 0.0, 1.0);
  MotionState m;
  if (p.run) {
    const DoubleSState st = p.profile.at(s * durations_[i]);
    m.q = s == 1 ? p.end : Eigen::VectorXd(p.start + st.p * p.direction);
    m.v = st.v * p.direction;
    m.a = st.a * p.direction;
    m.jerk = st.j * p.direction;
  } else {
    m = quintic_hermite(p.from, p.to, durations_[i], s);
  }
  if (scale_ != 1.0) {
    m.v /= scale_;
    m.a /= scale_ * scale_;
    m.jerk /= scale_ * scale_ * scale_;
  }
  return m;
}

MotionState Motion::at(double t) const {
  if (pieces_.empty()) throw std::logic_error("Motion: empty");
  const double u = t / scale_;
  if (u <= 0) return on_piece(0, 0.0);
  const auto it = std::upper_bound(starts_.begin(), starts_.end(), u);
  const size_t i = static_cast<size_t>(it - starts_.begin()) - 1;
  return on_piece(i, (u - starts_[i]) / durations_[i]);
}

void Motion::scale_time(double factor) {
  if (!(factor >= 1)) throw std::invalid_argument("Motion::scale_time: factor must be >= 1");
  scale_ *= factor;
}

}  // namespace demoplan
