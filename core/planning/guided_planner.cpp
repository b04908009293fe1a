#include <algorithm>
#include <chrono>
#include <map>
#include <queue>
#include <random>
#include <set>

#include "core/graph/projector.h"
#include "core/graph/state_validity.h"
#include "core/planning/nearest_neighbors.h"
#include "core/planning/planner.h"

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
            const PlannerParams& params, const ProgressCallback& progress, const std::atomic<bool>* cancel)
      : scene_(scene), graph_(graph), params_(params), progress_(progress), cancel_(cancel),
        projector_(scene, graph), validity_(scene, graph, checker, params.resolution),
        data_(checker.make_data()), forest_(static_cast<int>(graph.states.size()), scene.robot.model.nq),
        rng_(params.seed), sampled_(graph.transitions.size(), 0) {}

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
    std::uniform_real_distribution<double> u(0.0, 1.0);
    while (!connected()) {
      if (stop_requested(result)) break;
      ++iterations_;
      if (u(rng_) < params_.eta_sample_tree) sample_tree();
      else grow();
      report(false);
    }
    result.iterations = iterations_;
    result.trees = trees_created_;
    result.nodes = forest_.size();
    result.planning_time_s = elapsed();
    for (size_t s = 0; s < graph_.states.size(); ++s) result.state_nodes.push_back(forest_.state_size(static_cast<int>(s)));
    for (size_t t = 0; t < sampled_.size(); ++t)
      if (!sampled_[t]) result.unsampled_transitions.push_back(graph_.transitions[t].name);
    report(true);
    if (connected()) {
      result.solved = true;
      result.path = extract_path();
    } else if (result.message.empty()) {
      result.message = "no path within " + std::to_string(iterations_) + " iterations";
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
  bool cancelled() const { return cancel_ && cancel_->load(std::memory_order_relaxed); }
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
    if (elapsed() >= params_.time_limit) {
      r.message = "time limit (" + std::to_string(params_.time_limit) + " s) reached";
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
    pending_edges_.push_back({forest_.find(n.tree), n.state, forest_.node(a).q, n.q});
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
    if (!s.ok || !validity_.transition_free(s, data_)) return;
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
    if (progress_) pending_roots_.emplace_back(s.state_from, s.q_from());
    attempt_link(first);
    attempt_link(previous);
  }

  // Alg. 1, lines 15-25: one step of a tree in a random state towards a random configuration.
  void grow() {
    const std::vector<int> states = forest_.states_with_nodes();
    std::uniform_int_distribution<size_t> pick(0, states.size() - 1);
    const int state = states[pick(rng_)];
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
      if (cancelled() || elapsed() >= params_.time_limit) return;
      if (forest_.find(group) != group || forest_.find(forest_.node(id).tree) == group) continue;
      const Eigen::VectorXd q = forest_.node(id).q;
      int last = forest_.nearest_in(state, group, q);
      bool reached = false;
      while (true) {
        const Eigen::VectorXd& from = forest_.node(last).q;
        const Eigen::VectorXd d = q - from;
        const double len = d.norm();
        if (len <= params_.step) {
          reached = validity_.segment_free(state, from, q, data_);
          break;
        }
        const Eigen::VectorXd next = from + d * (params_.step / len);
        if (!validity_.configuration_free(state, next, data_) || !validity_.segment_free(state, from, next, data_)) break;
        last = add(next, state, forest_.node(last).tree, last, false);
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
    for (auto& e : pending_edges_) e.tree = forest_.tree_rank(forest_.find(e.tree));
    p.new_edges = std::move(pending_edges_);
    p.new_roots = std::move(pending_roots_);
    pending_edges_.clear();
    pending_roots_.clear();
    p.final = final;
    progress_(p);
  }

  // Shortest chain of nodes from start to goal (Dijkstra on joint-space length).
  Path extract_path() const {
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
    std::vector<int> chain;
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
  PlannerParams params_;
  const ProgressCallback& progress_;
  const std::atomic<bool>* cancel_;
  ConstraintProjector projector_;
  StateValidity validity_;
  CollisionData data_;
  Forest forest_;
  std::mt19937_64 rng_;
  std::vector<int> sampled_;  // collision-free roots per transition
  int start_ = -1, goal_ = -1;
  long iterations_ = 0;
  int trees_created_ = 0;
  Clock::time_point start_time_, last_progress_;
  std::vector<EdgeSnapshot> pending_edges_;
  std::vector<std::pair<int, Eigen::VectorXd>> pending_roots_;
};

}  // namespace

Path make_path(const Scene& scene, const ConstraintGraph& graph, const std::vector<Eigen::VectorXd>& qs,
               const std::vector<int>& states, const std::vector<char>& approach_to_next) {
  Path p;
  for (const Joint* j : scene.robot.model.configuration_joints()) p.joint_names.push_back(j->name);
  for (const auto& o : scene.objects) p.object_ids.push_back(o.id);
  for (size_t k = 0; k < qs.size(); ++k) {
    Waypoint w;
    w.q = qs[k];
    w.state = states[k];
    w.state_name = graph.states[states[k]].name;
    w.objects = scene_state(scene, graph, states[k], qs[k]).objects;
    w.approach = approach_to_next[k];
    const GraphState& s = graph.states[states[k]];
    // The gripper closes on entering a grasp state and opens on its last node before leaving.
    if (s.kind == StateKind::Grasp) {
      if (k > 0 && states[k - 1] != states[k]) w.action = GripperAction::Grasp, w.object = s.object;
      else if (k + 1 < qs.size() && states[k + 1] != states[k]) w.action = GripperAction::Release, w.object = s.object;
    }
    p.waypoints.push_back(std::move(w));
  }
  return p;
}

PlanResult plan_guided(const Scene& scene, const ConstraintGraph& graph, const CollisionChecker& checker,
                       const PlannerParams& params, const ProgressCallback& progress,
                       const std::atomic<bool>* cancel) {
  return GuidedRrt(scene, graph, checker, params, progress, cancel).run();
}

}  // namespace demoplan
