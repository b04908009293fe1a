#include "core/trajectory/trajectory.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace demoplan {

bool Trajectory::gripper_closed_at(double t) const {
  bool closed = starts_closed;
  for (size_t k = 0; k < actions.size(); ++k)
    if (actions[k] != GripperAction::None && waypoint_times[k] <= t) closed = actions[k] == GripperAction::Grasp;
  return closed;
}

TrajectorySample Trajectory::sample_at(double t) const {
  const MotionState m = motion.at(t);
  return {t, m.q, m.v, m.a, gripper_closed_at(t)};
}

std::vector<TrajectorySample> Trajectory::sample(double rate, bool include_waypoints) const {
  if (!(rate > 0 && std::isfinite(rate))) throw std::invalid_argument("Trajectory::sample: rate must be > 0");
  std::vector<double> times;
  const long n = static_cast<long>(std::floor(duration * rate + 1e-9));
  for (long i = 0; i <= n; ++i) times.push_back(std::min(duration, static_cast<double>(i) / rate));
  times.push_back(duration);
  if (include_waypoints) times.insert(times.end(), waypoint_times.begin(), waypoint_times.end());
  std::sort(times.begin(), times.end());
  // Times closer than 1 ns are one sample; a waypoint's exact time wins over a grid time.
  auto is_waypoint = [&](double t) {
    return include_waypoints && std::find(waypoint_times.begin(), waypoint_times.end(), t) != waypoint_times.end();
  };
  std::vector<double> unique;
  for (double t : times) {
    if (!unique.empty() && t - unique.back() < 1e-9) {
      if (is_waypoint(t)) unique.back() = t;
      continue;
    }
    unique.push_back(t);
  }
  std::vector<TrajectorySample> out;
  out.reserve(unique.size());
  for (double t : unique) out.push_back(sample_at(t));
  return out;
}

}  // namespace demoplan
