#pragma once
// A robot motion as a sequence of pieces: straight runs along a joint-space segment timed by a
// double-S profile, and quintic Hermite pieces between two states (the blends). Positions,
// velocities and accelerations are continuous; each piece is evaluated from its own exact
// description, so a phase of a few nanoseconds costs no precision.
#include <Eigen/Core>
#include <vector>

#include "core/trajectory/double_s.h"

namespace demoplan {

struct Knot {
  Eigen::VectorXd q, v, a;
};

struct MotionState {
  Eigen::VectorXd q, v, a, jerk;
};

// The quintic from `from` to `to` over `duration`, at fraction s in [0, 1].
MotionState quintic_hermite(const Knot& from, const Knot& to, double duration, double s);

class Motion {
public:
  // q = start + direction * p(t) for the profile's p; ends exactly at `end`.
  void add_run(const Eigen::VectorXd& start, const Eigen::VectorXd& end, const Eigen::VectorXd& direction,
               const DoubleS& profile);
  void add_quintic(const Knot& from, const Knot& to, double duration);

  double duration() const { return (starts_.empty() ? 0.0 : starts_.back() + durations_.back()) * scale_; }
  size_t pieces() const { return pieces_.size(); }
  double piece_start(size_t i) const { return starts_[i] * scale_; }
  double piece_duration(size_t i) const { return durations_[i] * scale_; }
  // The state at fraction s in [0, 1] of piece i; at(t) for a time, clamped to [0, duration()].
  MotionState on_piece(size_t i, double s) const;
  MotionState at(double t) const;
  // Stretches time uniformly by factor >= 1: velocities divide by it, accelerations by its square.
  void scale_time(double factor);

private:
  struct Piece {
    bool run = false;
    Eigen::VectorXd start, end, direction;  // run
    DoubleS profile;                        // run
    Knot from, to;                          // quintic
  };
  std::vector<Piece> pieces_;
  std::vector<double> starts_, durations_;  // unscaled
  double scale_ = 1.0;
};

}  // namespace demoplan
