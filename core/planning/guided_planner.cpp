#include <algorithm>
#include <chrono>
#include <limits>
#include <memory>
#include <random>
#include <set>

#include "core/graph/projector.h"
#include "core/graph/state_validity.h"
#include "core/planning/path_check.h"
#include "core/planning/roadmap.h"
#include "core/planning/guided_planner.h"
#include "core/planning/path_from_nodes.h"
#include "core/planning/regrasp.h"

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

  // Roots the start and goal trees; false when either end is in collision (finish() says which).
  bool begin() {
    start_time_ = Clock::now();
    last_progress_ = start_time_;
    CollisionPair hit;
    if (!validity_.configuration_free(graph_.start_state, graph_.q_start, data_, &hit)) {
      fail(result_, "the start configuration is in collision (" + hit.first + " / " + hit.second + ")");
      return false;
    }
    if (!validity_.configuration_free(graph_.goal_state, graph_.q_goal, data_, &hit)) {
      fail(result_, "the goal configuration is in collision (" + hit.first + " / " + hit.second + ")");
      return false;
    }
    start_ = roadmap_.add_node(graph_.q_start, graph_.start_state, roadmap_.new_tree());
    goal_ = roadmap_.add_node(graph_.q_goal, graph_.goal_state, roadmap_.new_tree());
    trees_created_ = 2;
    attempt_link(goal_);
    begun_ = true;
    return true;
  }

  enum class Outcome { Solved, Stopped, Paused };
  // Searches until start and goal share a tree along a path that passes the final check
  // (Solved), `stop` or the iteration limit ends it (Stopped), or `until` iterations are done
  // (Paused: advance() again resumes exactly where it paused).
  Outcome advance(long until = std::numeric_limits<long>::max()) {
    while (true) {
      while (!connected()) {
        if (iterations_ >= until) return Outcome::Paused;
        if (stop_requested(result_)) return Outcome::Stopped;
        ++iterations_;
        const int state = choose_step();
        if (state < 0) sample_tree();
        else grow(state);
        report(false);
      }
      result_.path = extract_path(chain_);
      // Lazy edges: the links the path uses are checked now (PlannerParams::lazy_edges).
      if (const int bad = first_colliding_link(chain_); bad >= 0) {
        cut(chain_[static_cast<size_t>(bad)], chain_[static_cast<size_t>(bad) + 1]);
        if (++result_.rejected_links >= params_.lazy_rejections) lazy_ = false;
        continue;
      }
      // Beyond the paper: see PlannerParams::final_check.
      if (!params_.final_check) return Outcome::Solved;
      const int bad = check_path(result_.path);
      if (cancelled()) {
        stop_requested(result_);
        return Outcome::Stopped;
      }
      if (bad < 0) return Outcome::Solved;
      cut(chain_[static_cast<size_t>(bad)], chain_[static_cast<size_t>(bad) + 1]);
      ++result_.rejected_paths;
    }
  }

  // The result after advance() returned `outcome` (or begin() failed).
  PlanResult finish(Outcome outcome) {
    PlanResult result = std::move(result_);
    if (!begun_) return result;
    result.iterations = iterations_;
    result.trees = trees_created_;
    result.nodes = roadmap_.size();
    result.planning_time_s = elapsed();
    for (size_t s = 0; s < graph_.states.size(); ++s) result.state_nodes.push_back(roadmap_.state_size(static_cast<int>(s)));
    for (size_t t = 0; t < sampled_.size(); ++t)
      if (!sampled_[t]) result.unsampled_transitions.push_back(graph_.transitions[t].name);
    report(true);
    if (outcome == Outcome::Solved) {
      result.solved = true;
    } else {
      result.path = {};
      if (result.message.empty()) result.message = "no path within " + std::to_string(iterations_) + " iterations";
    }
    return result;
  }

  long iterations() const { return iterations_; }
  int rejected_links() const { return result_.rejected_links; }
  const std::string& message() const { return result_.message; }  // why it stopped, once it has
  // A progress report if one is due: for work done beside the search (the regrasp sampling).
  void keep_reporting() { report(false); }

  // The picks where the search is stuck: the first pick the start's tree reaches the beginning
  // of but not the end, and the last one the goal's tree reaches the end of but not the
  // beginning (one pick when both agree); every pick when neither says.
  std::vector<int> stalled_picks() const {
    const std::vector<char> from_start = states_reached(start_), from_goal = states_reached(goal_);
    std::vector<int> out;
    const int n = static_cast<int>(graph_.picks.size());
    for (int k = 0; k < n; ++k) {
      const GraphPick& p = graph_.picks[static_cast<size_t>(k)];
      if (from_start[static_cast<size_t>(p.from)] && !from_start[static_cast<size_t>(p.to)]) {
        out.push_back(k);
        break;
      }
    }
    for (int k = n - 1; k >= 0; --k) {
      const GraphPick& p = graph_.picks[static_cast<size_t>(k)];
      if (from_goal[static_cast<size_t>(p.to)] && !from_goal[static_cast<size_t>(p.from)]) {
        if (std::find(out.begin(), out.end(), k) == out.end()) out.push_back(k);
        break;
      }
    }
    if (out.empty())
      for (int k = 0; k < n; ++k) out.push_back(k);
    return out;
  }

private:
  // The states a node's tree reaches over links known to be free: a lazy link not checked yet
  // may collide, and a pick reached only through one is not reached.
  std::vector<char> states_reached(int from) const {
    std::vector<char> seen(roadmap_.size(), 0), states(graph_.states.size(), 0);
    std::vector<int> stack{from};
    seen[static_cast<size_t>(from)] = 1;
    while (!stack.empty()) {
      const int u = stack.back();
      stack.pop_back();
      states[static_cast<size_t>(roadmap_.node(u).state)] = 1;
      for (const RoadmapLink& l : roadmap_.links(u))
        if (!seen[static_cast<size_t>(l.to)] && !unchecked_.count(key(u, l.to))) {
          seen[static_cast<size_t>(l.to)] = 1;
          stack.push_back(l.to);
        }
    }
    return states;
  }
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
    return lazy_ || validity_.segment_free(state, from, to, data_);
  }
  void mark_lazy(int a, int b) {
    if (lazy_) unchecked_.insert(key(a, b));
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
  bool lazy_ = params_.lazy_edges;  // whether new links are lazy (see PlannerParams::lazy_rejections)
  std::vector<std::vector<int>> roots_;  // per transition: the first node of each root
  PlanResult result_;  // filled as the search goes: message, rejected paths, the path found
  std::vector<int> chain_;
  bool begun_ = false;
  int start_ = -1, goal_ = -1;
  long iterations_ = 0;
  int trees_created_ = 0;
  Clock::time_point start_time_, last_progress_;
  std::vector<EdgeSnapshot> pending_edges_;
  std::vector<int> pending_edge_nodes_;  // the node each pending edge leads to
  std::vector<std::pair<int, Eigen::VectorXd>> pending_roots_;
};

// The regrasp phase of the guided planner (PlannerParams::regrasp_after): the demonstration as
// shown has not been solved in regrasp_after iterations. It goes on, and beside it variants are
// searched where a stalled pick has a regrasp (regrasp.h). Per round the demonstrated search gets
// regrasp_slice iterations and the variants as many together; a variant that has had
// regrasp_budget iterations gives its place to a new placement. Deterministic: iteration counts,
// no clocks, decide who runs.
class RegraspRounds {
public:
  RegraspRounds(const PlanningProblem& problem, const PlannerParams& params, GuidedRrt& demonstrated,
                const StopCondition& stop, const ProgressCallback& progress)
      : problem_(problem), params_(params), demonstrated_(demonstrated), stop_(stop), progress_(progress),
        rng_(params.seed), picks_(demonstrated.stalled_picks()) {
    // A variant reports its own states' names and every search's iterations.
    if (progress_)
      shown_ = [this](const PlannerProgress& p) {
        PlannerProgress q = p;
        q.iterations += others_;
        if (q.state_names.empty()) q.state_names = names_;
        progress_(q);
      };
  }

  // Runs the rounds until a search is solved or stopped.
  PlanResult run(Clock::time_point began) {
    for (int k = 0; k < params_.regrasp_candidates; ++k) {
      Variant v;
      if (!next_variant(v)) break;
      variants_.push_back(std::move(v));
    }
    GuidedRrt::Outcome outcome = GuidedRrt::Outcome::Paused;
    const long slice = std::max(1L, params_.regrasp_slice);
    while (outcome == GuidedRrt::Outcome::Paused) {
      others_ = total() - demonstrated_.iterations();
      // With no variant left the demonstrated search has the rest of the time to itself.
      outcome = demonstrated_.advance(variants_.empty() ? std::numeric_limits<long>::max()
                                                        : demonstrated_.iterations() + slice);
      if (outcome != GuidedRrt::Outcome::Paused) break;
      const long share = std::max(1L, slice / static_cast<long>(variants_.size()));
      for (size_t k = 0; k < variants_.size() && outcome == GuidedRrt::Outcome::Paused; ++k) {
        Variant& v = variants_[k];
        names_.clear();
        for (const GraphState& st : v.problem.graph->states) names_.push_back(st.name);
        others_ = total() - v.search->iterations();
        const GuidedRrt::Outcome o = v.search->advance(v.search->iterations() + share);
        if (o == GuidedRrt::Outcome::Solved) return solved_by(v, began);
        if (o == GuidedRrt::Outcome::Stopped) {
          outcome = o;
          stopped_because_ = v.search->message();  // the time limit or cancel, met in a variant
        }
        if (o == GuidedRrt::Outcome::Paused && v.search->iterations() >= params_.regrasp_budget) {
          retire(v);
          Variant fresh;
          if (next_variant(fresh)) v = std::move(fresh);
          else variants_.erase(variants_.begin() + static_cast<long>(k--));
        }
      }
    }
    others_ = total() - demonstrated_.iterations();
    const long iterations = total();
    PlanResult r = demonstrated_.finish(outcome);
    if (!stopped_because_.empty()) r.message = stopped_because_;
    r.cancelled = r.cancelled || stop_.cancelled();
    r.iterations = iterations;
    r.rejected_links += rejected_links_;
    for (const Variant& v : variants_) r.rejected_links += v.search->rejected_links();
    r.planning_time_s = std::chrono::duration<double>(Clock::now() - began).count();
    if (!r.solved && tried_ > 0)
      r.message += "; " + std::to_string(tried_) + " regrasp placements tried beside the demonstration";
    return r;
  }

private:
  struct Variant {
    Regrasp regrasp;
    PlanningProblem problem;
    std::unique_ptr<GuidedRrt> search;
  };

  // A variant with the next regrasp placement, the stalled picks taken in turn; false when none
  // of them has one left.
  bool next_variant(Variant& v) {
    const Scene& scene = *problem_.scene;
    while (dry_ < static_cast<int>(picks_.size()) && !stop_.should_stop()) {
      const int pick = picks_[static_cast<size_t>(pick_turn_++ % static_cast<int>(picks_.size()))];
      // The demonstrated search keeps reporting while placements are sampled.
      const std::vector<Regrasp> found = find_regrasps(scene, *problem_.demonstration, *problem_.checker, pick, 1,
                                                       rng_, stop_, 200, 8, [&] { demonstrated_.keep_reporting(); });
      if (found.empty()) {
        ++dry_;  // no placement in this pick's attempts: do not search it again
        continue;
      }
      dry_ = 0;
      v.regrasp = found.front();
      v.problem = make_planning_problem(problem_.scene, with_regrasp(*problem_.demonstration, v.regrasp),
                                        problem_.validation);
      PlannerParams vp = params_;
      vp.seed = params_.seed + static_cast<std::uint64_t>(++tried_);
      // A variant searches where the demonstrated search stalled, among close obstacles: there
      // lazy links mostly fail (tunnel_0/UR5/2: 6/10 solved with lazy variants, 10/10 eager).
      vp.lazy_edges = false;
      v.search = std::make_unique<GuidedRrt>(scene, *v.problem.graph, *problem_.checker, vp, shown_, stop_);
      if (v.search->begin()) return true;
    }
    return false;
  }

  void retire(const Variant& v) {
    retired_iterations_ += v.search->iterations();
    rejected_links_ += v.search->rejected_links();
  }

  PlanResult solved_by(Variant& v, Clock::time_point began) {
    const long iterations = total();
    const int rejected = rejected_links_ + demonstrated_.rejected_links();
    PlanResult r = v.search->finish(GuidedRrt::Outcome::Solved);
    r.iterations = iterations;
    r.rejected_links += rejected;
    r.planning_time_s = std::chrono::duration<double>(Clock::now() - began).count();
    r.graph = v.problem.graph;
    r.regrasp = describe(*problem_.scene, v.regrasp);
    return r;
  }

  // Iterations of every search so far.
  long total() const {
    long n = demonstrated_.iterations() + retired_iterations_;
    for (const Variant& v : variants_) n += v.search->iterations();
    return n;
  }

  const PlanningProblem& problem_;
  const PlannerParams& params_;
  GuidedRrt& demonstrated_;
  const StopCondition& stop_;
  const ProgressCallback& progress_;
  std::mt19937_64 rng_;  // placements
  const std::vector<int> picks_;
  std::vector<Variant> variants_;
  int tried_ = 0, pick_turn_ = 0, dry_ = 0;
  long others_ = 0;  // iterations of the searches not reporting, for the progress shown
  long retired_iterations_ = 0;
  int rejected_links_ = 0;  // of retired variants
  std::vector<std::string> names_;
  ProgressCallback shown_;
  std::string stopped_because_;
};

}  // namespace

PlanResult GuidedPlanner::solve(const PlanningProblem& problem, const StopCondition& stop,
                                 const ProgressCallback& progress) {
  const auto began = Clock::now();
  GuidedRrt demonstrated(*problem.scene, *problem.graph, *problem.checker, params_, progress, stop);
  if (!demonstrated.begin()) return demonstrated.finish(GuidedRrt::Outcome::Stopped);
  const bool regrasps = problem.demonstration && params_.regrasp_after > 0;
  const GuidedRrt::Outcome outcome =
      demonstrated.advance(regrasps ? params_.regrasp_after : std::numeric_limits<long>::max());
  if (outcome != GuidedRrt::Outcome::Paused) return demonstrated.finish(outcome);
  return RegraspRounds(problem, params_, demonstrated, stop, progress).run(began);
}

}  // namespace demoplan
