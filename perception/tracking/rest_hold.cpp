#include "perception/tracking/rest_hold.h"

#include <algorithm>

namespace demoplan::perception {

void RestHold::hold(int frame, size_t self, const std::vector<bool>& moving,
                    const std::vector<Eigen::Vector3d>& rested_at) {
  if (!on) {
    *this = RestHold();
    on = true;
    movers.assign(moving.size(), false);
    mover_from.resize(moving.size());
  }
  frames.push_back(frame);
  for (size_t j = 0; j < moving.size(); ++j)
    if (j != self && moving[j] && !movers[j]) {
      movers[j] = true;
      mover_from[j] = rested_at[j];
    }
}

bool RestHold::movers_at_rest(const std::vector<bool>& seen_last,
                              const std::vector<std::vector<Eigen::Vector2d>>& centres, double rest_px) const {
  for (size_t j = 0; on && j < movers.size(); ++j) {
    if (!movers[j]) continue;
    if (!seen_last[j] || centres[j].size() < 3) return false;
    for (const auto& c : centres[j])
      if ((c - centres[j].front()).norm() >= rest_px) return false;
  }
  return true;
}

bool RestHold::movers_rode(const std::vector<Eigen::Vector3d>& now, double min_move, double tolerance) const {
  if (!on) return false;
  std::vector<Eigen::Vector3d> moves;
  for (size_t j = 0; j < movers.size(); ++j)
    if (movers[j]) moves.push_back(now[j] - mover_from[j]);
  for (size_t a = 0; a < moves.size(); ++a)
    for (size_t b = a + 1; b < moves.size(); ++b)
      if (moves[a].norm() > min_move && moves[b].norm() > min_move &&
          (moves[a] - moves[b]).norm() < tolerance * std::max(moves[a].norm(), moves[b].norm()))
        return true;
  return false;
}

}  // namespace demoplan::perception
