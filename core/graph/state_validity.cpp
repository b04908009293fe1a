#include "core/graph/state_validity.h"

#include <cmath>
#include <utility>
#include <vector>

namespace demoplan {

StateValidity::StateValidity(const Scene& scene, const ConstraintGraph& graph,
                             const CollisionChecker& checker, double resolution)
    : scene_(scene), graph_(graph), checker_(checker), resolution_(resolution) {}

bool StateValidity::configuration_free(int state, const Eigen::VectorXd& q, CollisionData& data,
                                       CollisionPair* hit) const {
  return !checker_.in_collision(scene_state(scene_, graph_, state, q), data, {}, hit);
}

bool StateValidity::segment_free(int state, const Eigen::VectorXd& a, const Eigen::VectorXd& b,
                                 CollisionData& data, CollisionPair* hit) const {
  const int steps = static_cast<int>(std::ceil((b - a).norm() / resolution_));
  if (steps < 2) return true;
  SceneState s = scene_state(scene_, graph_, state, a);  // placements once; attachments follow q
  // Bisection order (the midpoint, then the halves' midpoints, breadth first): the samples of a
  // walk from a to b, so the same verdict, but an obstacle across the segment is met after a
  // few checks instead of after the walk reaches it.
  std::vector<std::pair<int, int>> spans{{0, steps}};
  spans.reserve(static_cast<size_t>(steps));
  for (size_t i = 0; i < spans.size(); ++i) {
    const auto [lo, hi] = spans[i];
    const int mid = (lo + hi) / 2;
    s.q = a + (b - a) * (static_cast<double>(mid) / steps);
    if (checker_.in_collision(s, data, {}, hit)) return false;
    if (mid - lo > 1) spans.emplace_back(lo, mid);
    if (hi - mid > 1) spans.emplace_back(mid, hi);
  }
  return true;
}

bool StateValidity::transition_free(const TransitionSample& t, CollisionData& data, CollisionPair* hit) const {
  const int edge = graph_.transitions[t.transition].edge_state();
  if (!configuration_free(t.state_from, t.q_from(), data, hit) || !configuration_free(t.state_to, t.q_to(), data, hit))
    return false;
  for (size_t k = 0; k + 1 < t.path.size(); ++k) {
    if (k > 0 && !configuration_free(edge, t.path[k], data, hit)) return false;
    if (!segment_free(edge, t.path[k], t.path[k + 1], data, hit)) return false;
  }
  return true;
}

}  // namespace demoplan
