#include <algorithm>
#include <chrono>
#include <map>
#include <queue>
#include <random>
#include <set>

#include "core/graph/projector.h"
#include "core/graph/state_validity.h"
#include "core/planning/nearest_neighbors.h"
#include "core/path/path_interpolation.h"
#include "core/planning/guided_planner.h"
#include "core/planning/path_from_nodes.h"

namespace demoplan {

namespace {

using Clock = std::chrono::steady_clock;

struct Node {
  Eigen::VectorXd q;
  int state;
  int tree;  // the tree it was added to (trees merge: see Forest::find)
};

struct Link {
  int to;
  bool approach;  // part of a transition's straight approach or retreat
};

// Trees as a union-find over tree ids, with per-state nearest-neighbour indexes: one over all
// nodes of a state (tree growth) and one per (state, merged tree) (attempt_link).
class Forest {
public:
  Forest(int states, int dim) : dim_(dim), all_(), groups_in_state_(states) {
    for (int s = 0; s < states; ++s) all_.emplace_back(dim);
  }

  int new_tree() {
    parent_.push_back(static_cast<int>(parent_.size()));
    return parent_.back();
  }
  int find(int t) const {
    while (parent_[t] != t) t = parent_[t];
    return t;
  }
  int add_node(const Eigen::VectorXd& q, int state, int tree) {
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
  void add_link(int a, int b, bool approach) {
    links_[a].push_back({b, approach});
    links_[b].push_back({a, approach});
  }
  // Merges two trees; the smaller one's indexes are moved into the larger one's.
  void merge(int a, int b) {
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
  // Removes the link between two nodes and recomputes the trees from the remaining links (the
  // union-find cannot split): used when a found path fails the final check.
  void cut(int a, int b) {
    auto drop = [&](int from, int to) {
      auto& l = links_[from];
      l.erase(std::remove_if(l.begin(), l.end(), [&](const Link& k) { return k.to == to; }), l.end());
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
        for (const Link& l : links_[u])
          if (tree[l.to] < 0) tree[l.to] = t, stack.push_back(l.to);
      }
    }
    for (size_t i = 0; i < nodes_.size(); ++i) {
      Node& n = nodes_[i];
      n.tree = tree[i];
      group_index(n.state, n.tree).add(static_cast<int>(i), n.q);
      groups_in_state_[n.state].insert(n.tree);
      ++nodes_in_group_[n.tree];
    }
  }
  int nearest(int state, const Eigen::VectorXd& q) const { return all_[state].nearest(q); }
  int random_node(int state, std::mt19937_64& rng) const {
    const auto& ids = all_[state].ids();
    return ids[std::uniform_int_distribution<size_t>(0, ids.size() - 1)(rng)];
  }
  int nearest_in(int state, int group, const Eigen::VectorXd& q) const {
    return by_group_.at({state, group}).nearest(q);
  }
  std::vector<int> groups_in(int state) const {
    return {groups_in_state_[state].begin(), groups_in_state_[state].end()};
  }
  size_t group_count(int state) const { return groups_in_state_[state].size(); }
  std::vector<int> states_with_nodes() const {
    std::vector<int> out;
    for (size_t s = 0; s < all_.size(); ++s)
      if (all_[s].size() > 0) out.push_back(static_cast<int>(s));
    return out;
  }
  const Node& node(int id) const { return nodes_[id]; }
  const std::vector<Link>& links(int id) const { return links_[id]; }
  size_t size() const { return nodes_.size(); }
  size_t state_size(int s) const { return all_[s].size(); }
  int tree_count() const { return static_cast<int>(nodes_in_group_.size()); }
  std::vector<size_t> tree_sizes() const {
    std::vector<size_t> out;
    for (const auto& [g, n] : nodes_in_group_) out.push_back(n);
    return out;
  }
  int tree_rank(int group) const {  // position of a merged tree in tree_sizes()
    int k = 0;
    for (const auto& [g, n] : nodes_in_group_) {
      if (g == group) return k;
      ++k;
    }
    return -1;
  }

private:
  NearestNeighbors& group_index(int state, int group) {
    auto it = by_group_.find({state, group});
    if (it == by_group_.end()) it = by_group_.emplace(std::make_pair(state, group), NearestNeighbors(dim_)).first;
    return it->second;
  }

  int dim_;
  std::vector<Node> nodes_;
  std::vector<std::vector<Link>> links_;
  std::vector<int> parent_;
  std::map<int, size_t> nodes_in_group_;
  std::vector<NearestNeighbors> all_;
  std::map<std::pair<int, int>, NearestNeighbors> by_group_;
  std::vector<std::set<int>> groups_in_state_;
};

class GuidedRrt {
public:
  GuidedRrt(const Scene& scene, const ConstraintGraph& graph, const CollisionChecker& checker,
            const PlannerParams& params, const ProgressCallback& progress, const StopCondition& stop)
      : scene_(scene), graph_(graph), checker_(checker), params_(params), progress_(progress), stop_(stop),
        projector_(scene, graph), validity_(scene, graph, checker, params.resolution),
        data_(checker.make_data()), forest_(static_cast<int>(graph.states.size()), scene.robot.model.nq),
        rng_(params.seed), sampled_(graph.transitions.size(), 0),
        roots_(graph.transitions.size()) {}

  PlanResult run() {
    start_time_ = Clock::now();
    last_progress_ = start_time_;
    PlanResult result;
    CollisionPair hit;
    if (!validity_.configuration_free(graph_.start_state, graph_.q_start, data_, &hit))
      return fail(result, "the start configuration is in collision (" + hit.first + " / " + hit.second + ")");
    if (!validity_.configuration_free(graph_.goal_state, graph_.q_goal, data_, &hit))
      return fail(result, "the goal configuration is in collision (" + hit.first + " / " + hit.second + ")");
    start_ = forest_.add_node(graph_.q_start, graph_.start_state, forest_.new_tree());
    goal_ = forest_.add_node(graph_.q_goal, graph_.goal_state, forest_.new_tree());
    trees_created_ = 2;
    attempt_link(goal_);
    std::vector<int> chain;
    bool accepted = false;
    while (true) {
      while (!connected()) {
        if (stop_requested(result)) break;
        ++iterations_;
        const int state = choose_step();
        if (state < 0) sample_tree();
        else grow(state);
        report(false);
      }
      if (!connected()) break;
      result.path = extract_path(chain);
      if (!params_.final_check) {
        accepted = true;
        break;
      }
      // Beyond the paper: see PlannerParams::final_check.
      const int bad = check_path(result.path);
      if (cancelled()) {
        stop_requested(result);
        break;
      }
      if (bad < 0) {
        accepted = true;
        break;
      }
      const int a = chain[static_cast<size_t>(bad)], b = chain[static_cast<size_t>(bad) + 1];
      forbidden_.insert({std::min(a, b), std::max(a, b)});
      forest_.cut(a, b);
      ++result.rejected_paths;
    }
    result.iterations = iterations_;
    result.trees = trees_created_;
    result.nodes = forest_.size();
    result.planning_time_s = elapsed();
    for (size_t s = 0; s < graph_.states.size(); ++s) result.state_nodes.push_back(forest_.state_size(static_cast<int>(s)));
    for (size_t t = 0; t < sampled_.size(); ++t)
      if (!sampled_[t]) result.unsampled_transitions.push_back(graph_.transitions[t].name);
    report(true);
    if (accepted) {
      result.solved = true;
    } else {
      result.path = {};
      if (result.message.empty()) result.message = "no path within " + std::to_string(iterations_) + " iterations";
    }
    return result;
  }

private:
  PlanResult& fail(PlanResult& r, const std::string& why) {
    r.message = why;
    r.planning_time_s = elapsed();
    return r;
  }
  double elapsed() const { return std::chrono::duration<double>(Clock::now() - start_time_).count(); }
  bool cancelled() const { return stop_.cancelled(); }
  bool stop_requested(PlanResult& r) {
    if (cancelled()) {
      r.cancelled = true;
      r.message = "cancelled after " + std::to_string(iterations_) + " iterations";
      return true;
    }
    if (iterations_ >= params_.max_iterations) {
      r.message = "iteration limit (" + std::to_string(params_.max_iterations) + ") reached";
      return true;
    }
    if (stop_.timed_out()) {
      r.message = "time limit (" + std::to_string(stop_.time_limit_s()) + " s) reached";
      return true;
    }
    return false;
  }
  bool connected() const { return forest_.find(forest_.node(start_).tree) == forest_.find(forest_.node(goal_).tree); }

  int add(const Eigen::VectorXd& q, int state, int tree, int link_to, bool approach) {
    const int id = forest_.add_node(q, state, tree);
    if (link_to >= 0) {
      forest_.add_link(link_to, id, approach);
      record_edge(link_to, id);
    }
    return id;
  }
  void record_edge(int a, int b) {
    if (!progress_) return;
    const Node& n = forest_.node(b);
    pending_edges_.push_back({-1, n.state, forest_.node(a).q, n.q});
    pending_edge_nodes_.push_back(b);
  }

  // Alg. 1, lines 4-14: a new tree at a sampled transition, linked to the trees of its states.
  void sample_tree() {
    // The paper draws k uniformly. Transitions that already root trees are drawn less often, so
    // the rare ones (a handle reachable from few arm configurations) get the samples.
    int t;
    if (params_.balance_transitions) {
      std::vector<double> w;
      for (int n : sampled_) w.push_back(1.0 / (1.0 + n));
      t = std::discrete_distribution<int>(w.begin(), w.end())(rng_);
    } else {
      t = std::uniform_int_distribution<int>(0, static_cast<int>(graph_.transitions.size()) - 1)(rng_);
    }
    // Seed the projection from a random node already in the state the transition leaves, when
    // there is one: the root then tends to lie near a tree and in the same IK branch.
    const int from = graph_.transitions[t].from;
    std::uniform_real_distribution<double> u(0.0, 1.0);
    const TransitionSample s = (forest_.state_size(from) > 0 && u(rng_) < params_.seed_from_trees)
                                   ? projector_.sample_on_transition(t, forest_.node(forest_.random_node(from, rng_)).q, rng_)
                                   : projector_.sample_on_transition(t, rng_);
    if (!s.ok) return;
    // A non-redundant arm reaches a handle in a few discrete ways: a projection often lands on
    // a root this transition has already. Another tree there would only repeat its links.
    for (const int r : roots_[t]) {
      const Node& n = forest_.node(r);
      if ((n.q - s.q_from()).norm() < params_.same_root) {
        ++sampled_[t];
        return;
      }
    }
    if (!validity_.transition_free(s, data_)) return;
    ++sampled_[t];
    const GraphTransition& tr = graph_.transitions[t];
    const int tree = forest_.new_tree();
    ++trees_created_;
    int previous = -1, first = -1;
    for (size_t k = 0; k < s.path.size(); ++k) {
      // Grasp: every node but the last rests in the placement state; release: all but the first.
      const bool in_to = tr.kind == TransitionKind::Grasp ? k + 1 == s.path.size() : k > 0;
      previous = add(s.path[k], in_to ? s.state_to : s.state_from, tree, previous, previous >= 0);
      if (first < 0) first = previous;
    }
    roots_[t].push_back(first);
    if (progress_) pending_roots_.emplace_back(s.state_from, s.q_from());
    attempt_link(first);
    attempt_link(previous);
  }

  // Alg. 1, line 4: -1 to sample a new tree (probability eta), else the state to grow in
  // (line 16). Beyond the paper: a state whose nodes all belong to one tree cannot link anything,
  // so it is drawn with weight lone_tree_weight instead of 1; the probability mass taken from
  // growth that way goes to sampling trees (eta is the probability when every state can link).
  int choose_step() {
    std::uniform_real_distribution<double> u(0.0, 1.0);
    const std::vector<int> states = forest_.states_with_nodes();
    if (params_.lone_tree_weight >= 1.0) {
      if (u(rng_) < params_.eta_sample_tree) return -1;
      return states[std::uniform_int_distribution<size_t>(0, states.size() - 1)(rng_)];
    }
    std::vector<double> w;
    double sum = 0.0;
    for (int s : states) {
      w.push_back(forest_.group_count(s) > 1 ? 1.0 : params_.lone_tree_weight);
      sum += w.back();
    }
    const double eta = params_.eta_sample_tree;
    const double grow_mass = (1.0 - eta) * sum / static_cast<double>(states.size());
    if (u(rng_) * (eta + grow_mass) < eta) return -1;
    return states[std::discrete_distribution<size_t>(w.begin(), w.end())(rng_)];
  }

  // Alg. 1, lines 15-25: one step of a tree in a state towards a random configuration.
  void grow(int state) {
    const Eigen::VectorXd q_rand = projector_.sample_configuration(state, rng_);
    const int nn = forest_.nearest(state, q_rand);
    const Eigen::VectorXd& q_nn = forest_.node(nn).q;
    const Eigen::VectorXd d = q_rand - q_nn;
    const double len = d.norm();
    if (len < 1e-9) return;
    const Eigen::VectorXd q_step = len <= params_.step ? q_rand : Eigen::VectorXd(q_nn + d * (params_.step / len));
    if (!validity_.configuration_free(state, q_step, data_) || !validity_.segment_free(state, q_nn, q_step, data_)) return;
    attempt_link(add(q_step, state, forest_.node(nn).tree, nn, false));
  }

  // Alg. 2: extend every other tree with nodes in this node's state towards it; merge on contact.
  void attempt_link(int id) {
    const int state = forest_.node(id).state;
    for (int group : forest_.groups_in(state)) {
      if (stop_.should_stop()) return;
      if (forest_.find(group) != group || forest_.find(forest_.node(id).tree) == group) continue;
      const Eigen::VectorXd q = forest_.node(id).q;
      int last = forest_.nearest_in(state, group, q);
      bool reached = false;
      while (true) {
        const Eigen::VectorXd& from = forest_.node(last).q;
        const Eigen::VectorXd d = q - from;
        const double len = d.norm();
        if (len <= params_.step) {
          reached = !forbidden_.count({std::min(last, id), std::max(last, id)}) &&
                    validity_.segment_free(state, from, q, data_);
          break;
        }
        const Eigen::VectorXd next = from + d * (params_.step / len);
        if (!validity_.configuration_free(state, next, data_) || !validity_.segment_free(state, from, next, data_)) break;
        last = add(next, state, forest_.node(last).tree, last, false);
        report(false);  // a long extension must not hold back progress or cancel
        if (cancelled()) break;
      }
      if (reached) {
        forest_.add_link(last, id, false);
        record_edge(last, id);
        forest_.merge(forest_.node(last).tree, forest_.node(id).tree);
        if (connected()) return;
      }
    }
  }

  void report(bool final) {
    if (!progress_) return;
    const auto now = Clock::now();
    if (!final && std::chrono::duration<double>(now - last_progress_).count() < params_.progress_period) return;
    last_progress_ = now;
    PlannerProgress p;
    p.elapsed_s = elapsed();
    p.iterations = iterations_;
    p.trees = forest_.tree_count();
    p.nodes = forest_.size();
    p.tree_nodes = forest_.tree_sizes();
    for (size_t s = 0; s < graph_.states.size(); ++s) p.state_nodes.push_back(forest_.state_size(static_cast<int>(s)));
    for (size_t k = 0; k < pending_edges_.size(); ++k)
      pending_edges_[k].tree = forest_.tree_rank(forest_.find(forest_.node(pending_edge_nodes_[k]).tree));
    p.new_edges = std::move(pending_edges_);
    p.new_roots = std::move(pending_roots_);
    pending_edges_.clear();
    pending_edge_nodes_.clear();
    pending_roots_.clear();
    p.final = final;
    progress_(p);
  }

  // The first segment of a found path (index of its first waypoint) with a collision at one of
  // the benchmark's samples (PlannerParams::final_check), -1 when there is none.
  int check_path(const Path& path) {
    const PathInterpolator interp(scene_, path);
    const std::vector<double> ts = interp.sample_parameters(params_.check_delta, params_.check_max_step);
    long count = 0;
    for (const double t : ts) {
      if (++count % 64 == 0) {
        report(false);
        if (cancelled()) return -1;
      }
      if (!checker_.in_collision(interp.at(t), data_)) continue;
      int k = 0;
      while (k + 2 < static_cast<int>(path.waypoints.size()) && interp.waypoint_parameter(static_cast<size_t>(k) + 1) <= t) ++k;
      return k;
    }
    return -1;
  }

  // Shortest chain of nodes from start to goal (Dijkstra on joint-space length).
  Path extract_path(std::vector<int>& chain) const {
    const size_t n = forest_.size();
    std::vector<double> dist(n, std::numeric_limits<double>::infinity());
    std::vector<int> prev(n, -1);
    std::priority_queue<std::pair<double, int>, std::vector<std::pair<double, int>>, std::greater<>> open;
    dist[start_] = 0.0;
    open.push({0.0, start_});
    while (!open.empty()) {
      const auto [d, u] = open.top();
      open.pop();
      if (d > dist[u]) continue;
      if (u == goal_) break;
      for (const Link& l : forest_.links(u)) {
        const double nd = d + (forest_.node(l.to).q - forest_.node(u).q).norm();
        if (nd < dist[l.to]) dist[l.to] = nd, prev[l.to] = u, open.push({nd, l.to});
      }
    }
    chain.clear();
    for (int v = goal_; v >= 0; v = prev[v]) chain.push_back(v);
    std::reverse(chain.begin(), chain.end());
    std::vector<Eigen::VectorXd> qs;
    std::vector<int> states;
    std::vector<char> approach;
    for (size_t k = 0; k < chain.size(); ++k) {
      qs.push_back(forest_.node(chain[k]).q);
      states.push_back(forest_.node(chain[k]).state);
      bool a = false;
      if (k + 1 < chain.size())
        for (const Link& l : forest_.links(chain[k]))
          if (l.to == chain[k + 1]) a = l.approach;
      approach.push_back(a);
    }
    return make_path(scene_, graph_, qs, states, approach);
  }

  const Scene& scene_;
  const ConstraintGraph& graph_;
  const CollisionChecker& checker_;
  PlannerParams params_;
  const ProgressCallback& progress_;
  const StopCondition& stop_;
  ConstraintProjector projector_;
  StateValidity validity_;
  CollisionData data_;
  Forest forest_;
  std::mt19937_64 rng_;
  std::vector<int> sampled_;  // collision-free samples per transition (repeated roots included)
  std::set<std::pair<int, int>> forbidden_;  // links cut after a failed path check
  std::vector<std::vector<int>> roots_;  // per transition: the first node of each root
  int start_ = -1, goal_ = -1;
  long iterations_ = 0;
  int trees_created_ = 0;
  Clock::time_point start_time_, last_progress_;
  std::vector<EdgeSnapshot> pending_edges_;
  std::vector<int> pending_edge_nodes_;  // the node each pending edge leads to
  std::vector<std::pair<int, Eigen::VectorXd>> pending_roots_;
};

}  // namespace

PlanResult GuidedPlanner::solve(const PlanningProblem& problem, const StopCondition& stop,
                                 const ProgressCallback& progress) {
  return GuidedRrt(*problem.scene, *problem.graph, *problem.checker, params_, progress, stop).run();
}

}  // namespace demoplan
