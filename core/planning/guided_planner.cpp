#include <algorithm>
#include <chrono>
#include <random>
#include <set>

#include "core/graph/projector.h"
#include "core/graph/state_validity.h"
#include "core/planning/path_check.h"
#include "core/planning/roadmap.h"
#include "core/planning/guided_planner.h"
#include "core/planning/path_from_nodes.h"

namespace demoplan {

namespace {

using Clock = std::chrono::steady_clock;

class GuidedRrt {
public:
  GuidedRrt(const Scene& scene, const ConstraintGraph& graph, const CollisionChecker& checker,
            const PlannerParams& params, const ProgressCallback& progress, const StopCondition& stop)
      : scene_(scene), graph_(graph), checker_(checker), params_(params), progress_(progress), stop_(stop),
        projector_(scene, graph), validity_(scene, graph, checker, params.resolution),
        data_(checker.make_data()), roadmap_(static_cast<int>(graph.states.size()), scene.robot.model.nq),
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
    start_ = roadmap_.add_node(graph_.q_start, graph_.start_state, roadmap_.new_tree());
    goal_ = roadmap_.add_node(graph_.q_goal, graph_.goal_state, roadmap_.new_tree());
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
      if (const int bad = first_colliding_link(chain); bad >= 0) {
        cut(chain[static_cast<size_t>(bad)], chain[static_cast<size_t>(bad) + 1]);
        ++result.rejected_links;
        continue;
      }
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
      cut(chain[static_cast<size_t>(bad)], chain[static_cast<size_t>(bad) + 1]);
      ++result.rejected_paths;
    }
    result.iterations = iterations_;
    result.trees = trees_created_;
    result.nodes = roadmap_.size();
    result.planning_time_s = elapsed();
    for (size_t s = 0; s < graph_.states.size(); ++s) result.state_nodes.push_back(roadmap_.state_size(static_cast<int>(s)));
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
  bool stop_requested(PlanResult& r) const {
    return demoplan::stop_requested(stop_, iterations_, params_.max_iterations, r);
  }
  bool connected() const { return roadmap_.find(roadmap_.node(start_).tree) == roadmap_.find(roadmap_.node(goal_).tree); }

  int add(const Eigen::VectorXd& q, int state, int tree, int link_to, bool approach) {
    const int id = roadmap_.add_node(q, state, tree);
    if (link_to >= 0) {
      roadmap_.add_link(link_to, id, approach);
      record_edge(link_to, id);
    }
    return id;
  }
  static std::pair<int, int> key(int a, int b) { return {std::min(a, b), std::max(a, b)}; }
  // Whether the straight link from `from` to `to` (both free) may be made: checked now, or with
  // lazy edges remembered and checked when a found path uses it.
  bool link_free(int state, const Eigen::VectorXd& from, const Eigen::VectorXd& to) {
    return params_.lazy_edges || validity_.segment_free(state, from, to, data_);
  }
  void mark_lazy(int a, int b) {
    if (params_.lazy_edges) unchecked_.insert(key(a, b));
  }
  // The first link of the chain that is unchecked and collides (its index), -1 when none; the
  // links found free are marked checked.
  int first_colliding_link(const std::vector<int>& chain) {
    for (size_t k = 0; k + 1 < chain.size(); ++k) {
      const auto it = unchecked_.find(key(chain[k], chain[k + 1]));
      if (it == unchecked_.end()) continue;
      const RoadmapNode &a = roadmap_.node(chain[k]), &b = roadmap_.node(chain[k + 1]);
      unchecked_.erase(it);
      if (!validity_.segment_free(a.state, a.q, b.q, data_)) return static_cast<int>(k);
    }
    return -1;
  }
  // A link a path cannot use: removed from the trees and never made again.
  void cut(int a, int b) {
    forbidden_.insert(key(a, b));
    unchecked_.erase(key(a, b));
    roadmap_.cut(a, b);
  }
  void record_edge(int a, int b) {
    if (!progress_) return;
    const RoadmapNode& n = roadmap_.node(b);
    pending_edges_.push_back({-1, n.state, roadmap_.node(a).q, n.q});
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
    const TransitionSample s = (roadmap_.state_size(from) > 0 && u(rng_) < params_.seed_from_trees)
                                   ? projector_.sample_on_transition(t, roadmap_.node(roadmap_.random_node(from, rng_)).q, rng_)
                                   : projector_.sample_on_transition(t, rng_);
    if (!s.ok) return;
    // A non-redundant arm reaches a handle in a few discrete ways: a projection often lands on
    // a root this transition has already. Another tree there would only repeat its links.
    for (const int r : roots_[t]) {
      const RoadmapNode& n = roadmap_.node(r);
      if ((n.q - s.q_from()).norm() < params_.same_root) {
        ++sampled_[t];
        return;
      }
    }
    if (!validity_.transition_free(s, data_)) return;
    ++sampled_[t];
    const GraphTransition& tr = graph_.transitions[t];
    const int tree = roadmap_.new_tree();
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
    const std::vector<int> states = roadmap_.states_with_nodes();
    if (params_.lone_tree_weight >= 1.0) {
      if (u(rng_) < params_.eta_sample_tree) return -1;
      return states[std::uniform_int_distribution<size_t>(0, states.size() - 1)(rng_)];
    }
    std::vector<double> w;
    double sum = 0.0;
    for (int s : states) {
      w.push_back(roadmap_.group_count(s) > 1 ? 1.0 : params_.lone_tree_weight);
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
    const int nn = roadmap_.nearest(state, q_rand);
    const Eigen::VectorXd& q_nn = roadmap_.node(nn).q;
    const Eigen::VectorXd d = q_rand - q_nn;
    const double len = d.norm();
    if (len < 1e-9) return;
    const Eigen::VectorXd q_step = len <= params_.step ? q_rand : Eigen::VectorXd(q_nn + d * (params_.step / len));
    if (!validity_.configuration_free(state, q_step, data_) || !link_free(state, q_nn, q_step)) return;
    const int id = add(q_step, state, roadmap_.node(nn).tree, nn, false);
    mark_lazy(nn, id);
    attempt_link(id);
  }

  // Alg. 2: extend every other tree with nodes in this node's state towards it; merge on contact.
  void attempt_link(int id) {
    const int state = roadmap_.node(id).state;
    for (int group : roadmap_.groups_in(state)) {
      if (stop_.should_stop()) return;
      if (roadmap_.find(group) != group || roadmap_.find(roadmap_.node(id).tree) == group) continue;
      const Eigen::VectorXd q = roadmap_.node(id).q;
      int last = roadmap_.nearest_in(state, group, q);
      bool reached = false;
      while (true) {
        const Eigen::VectorXd& from = roadmap_.node(last).q;
        const Eigen::VectorXd d = q - from;
        const double len = d.norm();
        if (len <= params_.step) {
          reached = !forbidden_.count(key(last, id)) && link_free(state, from, q);
          break;
        }
        const Eigen::VectorXd next = from + d * (params_.step / len);
        if (!validity_.configuration_free(state, next, data_) || !link_free(state, from, next)) break;
        const int previous = last;
        last = add(next, state, roadmap_.node(last).tree, last, false);
        mark_lazy(previous, last);
        report(false);  // a long extension must not hold back progress or cancel
        if (cancelled()) break;
      }
      if (reached) {
        roadmap_.add_link(last, id, false);
        mark_lazy(last, id);
        record_edge(last, id);
        roadmap_.merge(roadmap_.node(last).tree, roadmap_.node(id).tree);
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
    p.trees = roadmap_.tree_count();
    p.nodes = roadmap_.size();
    p.tree_nodes = roadmap_.tree_sizes();
    for (size_t s = 0; s < graph_.states.size(); ++s) p.state_nodes.push_back(roadmap_.state_size(static_cast<int>(s)));
    for (size_t k = 0; k < pending_edges_.size(); ++k)
      pending_edges_[k].tree = roadmap_.tree_rank(roadmap_.find(roadmap_.node(pending_edge_nodes_[k]).tree));
    p.new_edges = std::move(pending_edges_);
    p.new_roots = std::move(pending_roots_);
    pending_edges_.clear();
    pending_edge_nodes_.clear();
    pending_roots_.clear();
    p.final = final;
    progress_(p);
  }

  // See PlannerParams::final_check.
  int check_path(const Path& path) {
    return first_colliding_segment(scene_, checker_, data_, path, params_.check_delta, params_.check_max_step, [&] {
      report(false);
      return !cancelled();
    });
  }

  // Shortest chain of nodes from start to goal.
  Path extract_path(std::vector<int>& chain) const {
    chain = roadmap_.shortest_chain(start_, goal_);
    std::vector<Eigen::VectorXd> qs;
    std::vector<int> states;
    for (const int id : chain) {
      qs.push_back(roadmap_.node(id).q);
      states.push_back(roadmap_.node(id).state);
    }
    return make_path(scene_, graph_, qs, states, roadmap_.approach_flags(chain));
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
  Roadmap roadmap_;
  std::mt19937_64 rng_;
  std::vector<int> sampled_;  // collision-free samples per transition (repeated roots included)
  std::set<std::pair<int, int>> forbidden_;  // links cut after a failed path check
  std::set<std::pair<int, int>> unchecked_;  // lazy links not collision-checked yet
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
