#include "perception/tracking/ride_prediction.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include "core/geometry/planar_motion.h"

namespace demoplan::perception {

namespace {

GroupFit fit_group(const std::vector<size_t>& group, const std::vector<Eigen::Vector3d>& from,
                   const std::vector<RidePart>& parts, const RideRules& rules) {
  std::vector<Eigen::Vector3d> to;
  double longest = 0;
  for (size_t i = 0; i < group.size(); ++i) {
    to.push_back(parts[group[i]].now);
    longest = std::max(longest, (to.back() - from[i]).norm());
  }
  GroupFit g;
  g.motion = fit_planar_motion(from, to).at(1.0);
  double residual = 0;  // the farthest a moved rest lies from where its rider is now
  for (size_t i = 0; i < from.size(); ++i) residual = std::max(residual, (g.motion * from[i] - to[i]).norm());
  g.rigid = residual <= rules.tolerance + rules.tolerance_fraction * longest;
  return g;
}

}  // namespace

std::optional<Ride> Ride::detect(size_t self, const Eigen::Vector3d& rest, double bottom, double radius,
                                 const std::vector<RidePart>& parts, const RideRules& rules) {
  // The parts that have moved away from their rests. (The riders may stand far apart on a
  // long board: one of them rested beside this part is enough.)
  std::vector<size_t> moved;
  for (size_t j = 0; j < parts.size(); ++j) {
    const RidePart& p = parts[j];
    if (j != self && p.rest && p.tracked && p.left_rest >= 0 && (p.now - *p.rest).norm() > rules.min_move) moved.push_back(j);
  }
  auto beside = [&](size_t j) {
    return std::abs(parts[j].rest_bottom - bottom) < rules.height || (*parts[j].rest - rest).norm() < rules.radii * radius;
  };
  auto ride_of = [&](const std::vector<size_t>& riders) {
    Ride ride;
    for (size_t j : riders) {
      ride.riders_.push_back(j);
      ride.from_.push_back(*parts[j].rest);
      ride.left_.push_back(parts[j].left_rest);
    }
    return ride;
  };
  // Seeded by each pair that left together as one body: the others that went the same way
  // join; the largest group with a part that rested beside this one is the ride.
  std::optional<Ride> best;
  for (size_t a = 0; a < moved.size(); ++a)
    for (size_t b = a + 1; b < moved.size(); ++b) {
      auto together = [&](size_t j) {
        return std::abs(parts[j].left_rest - parts[moved[a]].left_rest) <= rules.start_frames &&
               std::abs(parts[j].left_rest - parts[moved[b]].left_rest) <= rules.start_frames;
      };
      if (!together(moved[b])) continue;
      std::vector<size_t> riders = {moved[a], moved[b]};
      if (!fit_group(riders, ride_of(riders).from_, parts, rules).rigid) continue;
      for (size_t c = 0; c < moved.size(); ++c) {
        if (c == a || c == b || !together(moved[c])) continue;
        riders.push_back(moved[c]);
        if (!fit_group(riders, ride_of(riders).from_, parts, rules).rigid) riders.pop_back();
      }
      if (std::none_of(riders.begin(), riders.end(), beside)) continue;
      if (!best || riders.size() > best->riders_.size()) best = ride_of(riders);
    }
  return best;
}

std::optional<Pose> Ride::motion(const std::vector<RidePart>& parts, const RideRules& rules) const {
  if (left_again(parts)) return std::nullopt;
  const std::optional<GroupFit> fit = fit_tracked(parts, rules);
  if (!fit || !fit->rigid) return std::nullopt;
  return fit->motion;
}

bool Ride::parted(const std::vector<RidePart>& parts, const RideRules& rules) const {
  if (left_again(parts)) return true;
  const std::optional<GroupFit> fit = fit_tracked(parts, rules);
  return fit && !fit->rigid;
}

bool Ride::left_again(const std::vector<RidePart>& parts) const {
  for (size_t i = 0; i < riders_.size(); ++i)
    if (parts[riders_[i]].left_rest > left_[i]) return true;
  return false;
}

std::optional<GroupFit> Ride::fit_tracked(const std::vector<RidePart>& parts, const RideRules& rules) const {
  std::vector<size_t> group;
  std::vector<Eigen::Vector3d> from;
  for (size_t i = 0; i < riders_.size(); ++i)
    if (parts[riders_[i]].tracked) {
      group.push_back(riders_[i]);
      from.push_back(from_[i]);
    }
  if (group.size() < 2) return std::nullopt;
  return fit_group(group, from, parts, rules);
}

}  // namespace demoplan::perception
