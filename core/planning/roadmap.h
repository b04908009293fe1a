#pragma once
// The multi-tree roadmap our sampling planners grow: nodes in graph states joined by
// collision-free straight links, trees as a union-find over tree ids (trees merge when a link
// joins them), and per-state nearest-neighbour indexes, one over every node of a state (growth)
// and one per (state, merged tree) (linking trees). States can be added while it grows (the
// unguided planner discovers its placement states).
#include <Eigen/Core>
#include <map>
#include <random>
#include <set>
#include <vector>

#include "core/planning/nearest_neighbors.h"

namespace demoplan {

struct RoadmapNode {
  Eigen::VectorXd q;
  int state;
  int tree;  // the tree it was added to (trees merge: see Roadmap::find)
};

struct RoadmapLink {
  int to;
  bool approach;  // part of a transition's straight approach or retreat
};

class Roadmap {
public:
  Roadmap(int states, int dim);

  int add_state();  // a new empty state; returns its index
  void pop_state();  // removes the last state, which must have no node
  int new_tree();
  int find(int tree) const;
  int add_node(const Eigen::VectorXd& q, int state, int tree);
  void add_link(int a, int b, bool approach);
  // Merges two trees; the smaller one's indexes are moved into the larger one's.
  void merge(int a, int b);
  // Removes the link between two nodes and recomputes the trees from the remaining links (the
  // union-find cannot split): used when a found path fails the final check.
  void cut(int a, int b);

  int nearest(int state, const Eigen::VectorXd& q) const;
  int random_node(int state, std::mt19937_64& rng) const;
  int nearest_in(int state, int group, const Eigen::VectorXd& q) const;
  // Nearest node of a merged tree over all its states, -1 when it has none.
  int nearest_in_tree(int group, const Eigen::VectorXd& q) const;
  std::vector<int> groups_in(int state) const;
  size_t group_count(int state) const { return groups_in_state_[state].size(); }
  std::vector<int> states_with_nodes() const;
  const RoadmapNode& node(int id) const { return nodes_[id]; }
  const std::vector<RoadmapLink>& links(int id) const { return links_[id]; }
  size_t size() const { return nodes_.size(); }
  size_t state_size(int s) const { return all_[s].size(); }
  int state_count() const { return static_cast<int>(all_.size()); }
  int tree_count() const { return static_cast<int>(nodes_in_group_.size()); }
  std::vector<size_t> tree_sizes() const;
  int tree_rank(int group) const;  // position of a merged tree in tree_sizes()
  bool same_tree(int a, int b) const { return find(nodes_[a].tree) == find(nodes_[b].tree); }

  // Shortest chain of nodes from `from` to `to` over the links (Dijkstra on joint-space length);
  // empty when they are not connected.
  std::vector<int> shortest_chain(int from, int to) const;
  // Whether the link from chain[k] to chain[k + 1] is an approach, per node of the chain.
  std::vector<char> approach_flags(const std::vector<int>& chain) const;

private:
  NearestNeighbors& group_index(int state, int group);

  int dim_;
  std::vector<RoadmapNode> nodes_;
  std::vector<std::vector<RoadmapLink>> links_;
  std::vector<int> parent_;
  std::map<int, size_t> nodes_in_group_;
  std::vector<NearestNeighbors> all_;
  std::map<std::pair<int, int>, NearestNeighbors> by_group_;
  std::vector<std::set<int>> groups_in_state_;
};

}  // namespace demoplan
