#include "core/planning/connect_in_state.h"

#include <algorithm>

namespace demoplan {

namespace {

struct Tree {
  std::vector<Eigen::VectorXd> q;
  std::vector<int> parent;
  int add(const Eigen::VectorXd& x, int p) {
    q.push_back(x);
    parent.push_back(p);
    return static_cast<int>(q.size()) - 1;
  }
  int nearest(const Eigen::VectorXd& x) const {
    int best = 0;
    double d = (q[0] - x).squaredNorm();
    for (size_t i = 1; i < q.size(); ++i) {
      const double di = (q[i] - x).squaredNorm();
      if (di < d) d = di, best = static_cast<int>(i);
    }
    return best;
  }
  std::vector<Eigen::VectorXd> to_root(int i) const {
    std::vector<Eigen::VectorXd> out;
    for (; i >= 0; i = parent[i]) out.push_back(q[i]);
    return out;
  }
};

enum class Extend { Trapped, Advanced, Reached };

}  // namespace

std::optional<std::vector<Eigen::VectorXd>> connect_in_state(const ConstraintProjector& sampler,
                                                              const StateValidity& validity, CollisionData& data,
                                                              int state, const Eigen::VectorXd& a,
                                                              const Eigen::VectorXd& b, std::mt19937_64& rng,
                                                              const ConnectParams& params) {
  if (params.straight_first && validity.segment_free(state, a, b, data)) return std::vector<Eigen::VectorXd>{};
  Tree ta, tb;
  ta.add(a, -1);
  tb.add(b, -1);
  // One step of `t` from its node nearest to `target`; the new node's index in `*last`.
  auto extend = [&](Tree& t, const Eigen::VectorXd& target, int* last) {
    const int n = t.nearest(target);
    const Eigen::VectorXd d = target - t.q[n];
    const double len = d.norm();
    const bool reaches = len <= params.step;
    const Eigen::VectorXd next = reaches ? target : Eigen::VectorXd(t.q[n] + d * (params.step / len));
    if (!validity.configuration_free(state, next, data) || !validity.segment_free(state, t.q[n], next, data))
      return Extend::Trapped;
    *last = t.add(next, n);
    return reaches ? Extend::Reached : Extend::Advanced;
  };
  Tree* grow = &ta;
  Tree* other = &tb;
  for (long round = 0; round < params.max_rounds && std::chrono::steady_clock::now() < params.deadline; ++round) {
    int from = -1, to = -1;
    if (extend(*grow, sampler.sample_configuration(state, rng), &from) == Extend::Trapped) {
      std::swap(grow, other);
      continue;
    }
    Extend e = Extend::Advanced;
    while (e == Extend::Advanced && std::chrono::steady_clock::now() < params.deadline)
      e = extend(*other, grow->q[from], &to);
    if (e == Extend::Reached) {
      const int in_a = grow == &ta ? from : to, in_b = grow == &ta ? to : from;  // the meeting node
      std::vector<Eigen::VectorXd> from_a = ta.to_root(in_a), from_b = tb.to_root(in_b);
      // from_a runs from the meeting node back to a, from_b from the meeting node (its copy in
      // the other tree) to b: a ... meeting ... b, returned without its ends.
      std::reverse(from_a.begin(), from_a.end());
      std::vector<Eigen::VectorXd> full = std::move(from_a);
      full.insert(full.end(), from_b.begin() + 1, from_b.end());
      return std::vector<Eigen::VectorXd>(full.begin() + 1, full.end() - 1);
    }
    std::swap(grow, other);
  }
  return std::nullopt;
}

}  // namespace demoplan
