#pragma once
// The time-optimal jerk-limited ("double S") motion along a straight line of length h > 0, from
// speed v0 to speed v1 with zero acceleration at both ends (Biagiotti and Melchiorri,
// "Trajectory Planning for Automatic Machines and Robots", sec. 3.4). Seven phases: jerk up,
// constant acceleration, jerk down, cruise, and the same mirrored for the deceleration.
#include <vector>

namespace demoplan {

struct DoubleSLimits {
  double velocity, acceleration, jerk;  // > 0
};

struct DoubleSState {
  double p = 0, v = 0, a = 0, j = 0;
};

struct DoubleS {
  double h = 0, v0 = 0, v1 = 0, jerk = 0;
  double Ta = 0, Tv = 0, Td = 0, Tj1 = 0, Tj2 = 0;  // phase durations
  double a_acc = 0, a_dec = 0, v_lim = 0;           // reached acceleration (>=0), deceleration (<=0), speed

  double duration() const { return Ta + Tv + Td; }
  DoubleSState at(double t) const;  // clamped to [0, duration()]
  // Ends of the constant-jerk pieces, 0 first, duration() last, without repeats.
  std::vector<double> phase_times() const;
};

// Whether a profile from v0 to v1 fits in length h (both speeds within the velocity limit).
bool double_s_feasible(double h, double v0, double v1, const DoubleSLimits& limits);
// The highest end speed (<= limits.velocity) a profile from v0 can reach within length h.
double double_s_reach(double h, double v0, const DoubleSLimits& limits);
// The profile; requires double_s_feasible(h, v0, v1, limits).
DoubleS plan_double_s(double h, double v0, double v1, const DoubleSLimits& limits);

}  // namespace demoplan
