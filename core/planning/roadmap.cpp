#include "core/planning/roadmap.h"

#include <algorithm>
#include <cassert>
#include <limits>
#include <queue>

namespace demoplan {

Roadmap::Roadmap(int states, int dim) : dim_(dim) {
  for (int s = 0; s < states; ++s) add_state();
}

int Roadmap::add_state() {
  all_.emplace_back(dim_);
  groups_in_state_.emplace_back();
  return static_cast<int>(all_.size()) - 1;
}

void Roadmap::pop_state() {
  assert(all_.back().size() == 0 && groups_in_state_.back().empty());
  all_.pop_back();
  groups_in_state_.pop_back();
}

int Roadmap::new_tree() {
  parent_.push_back(static_cast<int>(parent_.size()));
  return parent_.back();
}

int Roadmap::find(int t) const {
  while (parent_[t] != t) t = parent_[t];
  return t;
}

int Roadmap::add_node(const Eigen::VectorXd& q, int state, int tree) {
  const int id = static_cast<int>(nodes_.size());
  nodes_.push_back({q, state, tree});
  links_.emplace_back();
  all_[state].add(id, q);
  const int g = find(tree);
  group_index(state, g).add(id, q);
  groups_in_state_[state].insert(g);
  ++nodes_in_group_[g];
  return id;
}

void Roadmap::add_link(int a, int b, bool approach) {
  links_[a].push_back({b, approach});
  links_[b].push_back({a, approach});
}

void Roadmap::merge(int a, int b) {
  a = find(a), b = find(b);
  if (a == b) return;
  if (nodes_in_group_[a] < nodes_in_group_[b]) std::swap(a, b);
  parent_[b] = a;
  nodes_in_group_[a] += nodes_in_group_[b];
  nodes_in_group_.erase(b);
  for (size_t s = 0; s < groups_in_state_.size(); ++s) {
    auto it = by_group_.find({static_cast<int>(s), b});
    if (it == by_group_.end()) continue;
    NearestNeighbors& into = group_index(static_cast<int>(s), a);
    for (int id : it->second.ids()) into.add(id, nodes_[id].q);
    by_group_.erase(it);
    groups_in_state_[s].erase(b);
    groups_in_state_[s].insert(a);
  }
}

void Roadmap::cut(int a, int b) {
  auto drop = [&](int from, int to) {
    auto& l = links_[from];
    l.erase(std::remove_if(l.begin(), l.end(), [&](const RoadmapLink& k) { return k.to == to; }), l.end());
  };
  drop(a, b);
  drop(b, a);
  parent_.clear();
  nodes_in_group_.clear();
  by_group_.clear();
  for (auto& g : groups_in_state_) g.clear();
  std::vector<int> tree(nodes_.size(), -1);
  std::vector<int> stack;
  for (size_t i = 0; i < nodes_.size(); ++i) {
    if (tree[i] >= 0) continue;
    const int t = new_tree();
    tree[i] = t;
    stack.push_back(static_cast<int>(i));
    while (!stack.empty()) {
      const int u = stack.back();
      stack.pop_back();
      for (const RoadmapLink& l : links_[u])
        if (tree[l.to] < 0) tree[l.to] = t, stack.push_back(l.to);
    }
  }
  for (size_t i = 0; i < nodes_.size(); ++i) {
    RoadmapNode& n = nodes_[i];
    n.tree = tree[i];
    group_index(n.state, n.tree).add(static_cast<int>(i), n.q);
    groups_in_state_[n.state].insert(n.tree);
    ++nodes_in_group_[n.tree];
  }
}

int Roadmap::nearest(int state, const Eigen::VectorXd& q) const { return all_[state].nearest(q); }

int Roadmap::random_node(int state, std::mt19937_64& rng) const {
  const auto& ids = all_[state].ids();
  return ids[std::uniform_int_distribution<size_t>(0, ids.size() - 1)(rng)];
}

int Roadmap::nearest_in(int state, int group, const Eigen::VectorXd& q) const {
  return by_group_.at({state, group}).nearest(q);
}

int Roadmap::nearest_in_tree(int group, const Eigen::VectorXd& q) const {
  int best = -1;
  double best_d = std::numeric_limits<double>::infinity();
  for (auto it = by_group_.begin(); it != by_group_.end(); ++it) {
    if (it->first.second != group) continue;
    double d = 0.0;
    const int id = it->second.nearest(q, &d);
    if (id >= 0 && d < best_d) best = id, best_d = d;
  }
  return best;
}

std::vector<int> Roadmap::groups_in(int state) const {
  return {groups_in_state_[state].begin(), groups_in_state_[state].end()};
}

std::vector<int> Roadmap::states_with_nodes() const {
  std::vector<int> out;
  for (size_t s = 0; s < all_.size(); ++s)
    if (all_[s].size() > 0) out.push_back(static_cast<int>(s));
  return out;
}

std::vector<size_t> Roadmap::tree_sizes() const {
  std::vector<size_t> out;
  for (const auto& [g, n] : nodes_in_group_) out.push_back(n);
  return out;
}

int Roadmap::tree_rank(int group) const {
  int k = 0;
  for (const auto& [g, n] : nodes_in_group_) {
    if (g == group) return k;
    ++k;
  }
  return -1;
}

std::vector<int> Roadmap::shortest_chain(int from, int to) const {
  const size_t n = nodes_.size();
  std::vector<double> dist(n, std::numeric_limits<double>::infinity());
  std::vector<int> prev(n, -1);
  std::priority_queue<std::pair<double, int>, std::vector<std::pair<double, int>>, std::greater<>> open;
  dist[from] = 0.0;
  open.push({0.0, from});
  while (!open.empty()) {
    const auto [d, u] = open.top();
    open.pop();
    if (d > dist[u]) continue;
    if (u == to) break;
    for (const RoadmapLink& l : links_[u]) {
      const double nd = d + (nodes_[l.to].q - nodes_[u].q).norm();
      if (nd < dist[l.to]) dist[l.to] = nd, prev[l.to] = u, open.push({nd, l.to});
    }
  }
  std::vector<int> chain;
  if (from != to && prev[to] < 0) return chain;
  for (int v = to; v >= 0; v = prev[v]) chain.push_back(v);
  std::reverse(chain.begin(), chain.end());
  return chain;
}

NearestNeighbors& Roadmap::group_index(int state, int group) {
  auto it = by_group_.find({state, group});
  if (it == by_group_.end()) it = by_group_.emplace(std::make_pair(state, group), NearestNeighbors(dim_)).first;
  return it->second;
}

std::vector<char> Roadmap::approach_flags(const std::vector<int>& chain) const {
  std::vector<char> approach;
  for (size_t k = 0; k < chain.size(); ++k) {
    bool a = false;
    if (k + 1 < chain.size())
      for (const RoadmapLink& l : links_[chain[k]])
        if (l.to == chain[k + 1]) a = l.approach;
    approach.push_back(a);
  }
  return approach;
}

}  // namespace demoplan
