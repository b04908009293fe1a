#include "core/trajectory/double_s.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace demoplan {

bool double_s_feasible(double h, double v0, double v1, const DoubleSLimits& l) {
  // Biagiotti and Melchiorri eq. 3.17-3.18: the shortest length over which the speed can change
  // from v0 to v1 with zero end accelerations.
  const double dv = std::abs(v1 - v0);
  const double tj = std::min(std::sqrt(dv / l.jerk), l.acceleration / l.jerk);
  const double needed = tj < l.acceleration / l.jerk ? tj * (v0 + v1) : 0.5 * (v0 + v1) * (tj + dv / l.acceleration);
  return h >= needed;
}

double double_s_reach(double h, double v0, const DoubleSLimits& l) {
  if (double_s_feasible(h, v0, l.velocity, l)) return l.velocity;
  // The needed length grows with the end speed above v0, and v1 = v0 always fits.
  double lo = std::min(v0, l.velocity), hi = l.velocity;
  for (int i = 0; i < 60; ++i) {
    const double mid = 0.5 * (lo + hi);
    (double_s_feasible(h, v0, mid, l) ? lo : hi) = mid;
  }
  return lo;
}

DoubleS plan_double_s(double h, double v0, double v1, const DoubleSLimits& l) {
  if (!(h > 0) || v0 < 0 || v1 < 0 || v0 > l.velocity * (1 + 1e-12) || v1 > l.velocity * (1 + 1e-12))
    throw std::invalid_argument("plan_double_s: bad boundary conditions");
  DoubleS s;
  s.h = h, s.v0 = v0, s.v1 = v1, s.jerk = l.jerk;
  const double j = l.jerk, vmax = l.velocity;
  double amax = l.acceleration;
  // Case 1: the cruise speed vmax is reached.
  if ((vmax - v0) * j < amax * amax) s.Tj1 = std::sqrt(std::max(0.0, vmax - v0) / j), s.Ta = 2 * s.Tj1;
  else s.Tj1 = amax / j, s.Ta = s.Tj1 + (vmax - v0) / amax;
  if ((vmax - v1) * j < amax * amax) s.Tj2 = std::sqrt(std::max(0.0, vmax - v1) / j), s.Td = 2 * s.Tj2;
  else s.Tj2 = amax / j, s.Td = s.Tj2 + (vmax - v1) / amax;
  s.Tv = h / vmax - s.Ta / 2 * (1 + v0 / vmax) - s.Td / 2 * (1 + v1 / vmax);
  if (s.Tv <= 0) {
    // Case 2: no cruise; lower the acceleration until both ramps have their constant part.
    s.Tv = 0;
    for (int iter = 0;; ++iter) {
      const double tj = amax / j;
      const double delta = std::pow(amax, 4) / (j * j) + 2 * (v0 * v0 + v1 * v1) +
                           amax * (4 * h - 2 * amax / j * (v0 + v1));
      s.Tj1 = s.Tj2 = tj;
      s.Ta = (amax * amax / j - 2 * v0 + std::sqrt(std::max(0.0, delta))) / (2 * amax);
      s.Td = (amax * amax / j - 2 * v1 + std::sqrt(std::max(0.0, delta))) / (2 * amax);
      if (s.Ta < 0) {  // decelerate only
        s.Ta = s.Tj1 = 0;
        s.Td = 2 * h / (v1 + v0);
        // At the feasibility boundary rounding can make the root's argument slightly negative.
        s.Tj2 = (j * h - std::sqrt(std::max(0.0, j * (j * h * h + (v1 + v0) * (v1 + v0) * (v1 - v0))))) / (j * (v1 + v0));
        s.Tj2 = std::clamp(s.Tj2, 0.0, s.Td / 2);
        break;
      }
      if (s.Td < 0) {  // accelerate only
        s.Td = s.Tj2 = 0;
        s.Ta = 2 * h / (v1 + v0);
        s.Tj1 = (j * h - std::sqrt(std::max(0.0, j * (j * h * h - (v1 + v0) * (v1 + v0) * (v1 - v0))))) / (j * (v1 + v0));
        s.Tj1 = std::clamp(s.Tj1, 0.0, s.Ta / 2);
        break;
      }
      if ((s.Ta >= 2 * tj && s.Td >= 2 * tj) || iter > 5000) break;
      amax *= 0.99;
    }
  }
  s.a_acc = j * s.Tj1;
  s.a_dec = -j * s.Tj2;
  if (s.Ta == 0) s.v_lim = v0;  // decelerate only
  else if (s.Td == 0) s.v_lim = v1;  // accelerate only
  else s.v_lim = v0 + (s.Ta - s.Tj1) * s.a_acc;
  return s;
}

DoubleSState DoubleS::at(double t) const {
  const double T = duration();
  t = std::clamp(t, 0.0, T);
  DoubleSState st;
  if (t < Tj1) {
    st.p = v0 * t + jerk * t * t * t / 6;
    st.v = v0 + jerk * t * t / 2;
    st.a = jerk * t;
    st.j = jerk;
  } else if (t < Ta - Tj1) {
    st.p = v0 * t + a_acc / 6 * (3 * t * t - 3 * Tj1 * t + Tj1 * Tj1);
    st.v = v0 + a_acc * (t - Tj1 / 2);
    st.a = a_acc;
  } else if (t < Ta) {
    const double r = Ta - t;
    st.p = (v_lim + v0) * Ta / 2 - v_lim * r + jerk * r * r * r / 6;
    st.v = v_lim - jerk * r * r / 2;
    st.a = jerk * r;
    st.j = -jerk;
  } else if (t < Ta + Tv) {
    st.p = (v_lim + v0) * Ta / 2 + v_lim * (t - Ta);
    st.v = v_lim;
  } else if (t < T - Td + Tj2) {
    const double u = t - T + Td;
    st.p = h - (v_lim + v1) * Td / 2 + v_lim * u - jerk * u * u * u / 6;
    st.v = v_lim - jerk * u * u / 2;
    st.a = -jerk * u;
    st.j = -jerk;
  } else if (t < T - Tj2) {
    const double u = t - T + Td;
    st.p = h - (v_lim + v1) * Td / 2 + v_lim * u + a_dec / 6 * (3 * u * u - 3 * Tj2 * u + Tj2 * Tj2);
    st.v = v_lim + a_dec * (u - Tj2 / 2);
    st.a = a_dec;
  } else {
    const double r = T - t;
    st.p = h - v1 * r - jerk * r * r * r / 6;
    st.v = v1 + jerk * r * r / 2;
    st.a = -jerk * r;
    st.j = jerk;
  }
  return st;
}

std::vector<double> DoubleS::phase_times() const {
  const double T = duration();
  std::vector<double> ts{0.0, Tj1, Ta - Tj1, Ta, Ta + Tv, Ta + Tv + Tj2, T - Tj2, T};
  std::vector<double> out;
  for (double t : ts) {
    t = std::clamp(t, 0.0, T);
    if (out.empty() || t > out.back() + 1e-12) out.push_back(t);
  }
  out.back() = T;
  return out;
}

}  // namespace demoplan
