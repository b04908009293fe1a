#include "core/planning/unguided_planner.h"

#include <chrono>
#include <map>
#include <random>
#include <set>

#include "core/graph/projector.h"
#include "core/graph/state_validity.h"
#include "core/planning/path_check.h"
#include "core/planning/path_from_nodes.h"
#include "core/planning/roadmap.h"
#include "core/scene/resting_pose_sampler.h"

namespace demoplan {

namespace {

using Clock = std::chrono::steady_clock;

// The problem's graph reduced to what the unguided planner may know: the start and goal
// placements (states 0 and 1, or one state when nothing moves) and the robot's joints.
std::shared_ptr<ConstraintGraph> start_and_goal(const ConstraintGraph& g) {
  auto out = std::make_shared<ConstraintGraph>();
  out->reach_joints = g.reach_joints;
  out->gripper_joints = g.gripper_joints;
  out->gripper_open = g.gripper_open;
  out->q_start = g.q_start;
  out->q_goal = g.q_goal;
  GraphState start = g.states[g.start_state];
  start.name = "start";
  start.step = -1;
  out->states.push_back(start);
  out->start_state = 0;
  out->goal_state = 0;
  if (!same_placements(start.objects, g.states[g.goal_state].objects)) {
    GraphState goal = g.states[g.goal_state];
    goal.name = "goal";
    goal.step = -1;
    out->states.push_back(goal);
    out->goal_state = 1;
  }
  return out;
}

class UnguidedRrt {
public:
  UnguidedRrt(const PlanningProblem& problem, const PlannerParams& params, const UnguidedParams& unguided,
              const ProgressCallback& progress, const StopCondition& stop)
      : scene_(*problem.scene), checker_(*problem.checker), params_(params), unguided_(unguided),
        progress_(progress), stop_(stop), graph_(start_and_goal(*problem.graph)), projector_(scene_, *graph_),
        validity_(scene_, *graph_, checker_, params.resolution), placements_(scene_), data_(checker_.make_data()),
        roadmap_(static_cast<int>(graph_->states.size()), scene_.robot.model.nq), rng_(params.seed) {
    const double opening = scene_.robot.gripper().clearance;
    for (const auto& o : scene_.objects) {
      std::vector<int> handles;
      for (size_t h = 0; h < o.srdf.handles.size(); ++h)
        if (o.srdf.handles[h].clearance <= opening) handles.push_back(static_cast<int>(h));
      handles_.push_back(std::move(handles));
    }
  }

  PlanResult run() {
    start_time_ = last_progress_ = Clock::now();
    PlanResult result;
    result.graph = graph_;
    CollisionPair hit;
    if (!validity_.configuration_free(graph_->start_state, graph_->q_start, data_, &hit))
      return fail(result, "the start configuration is in collision (" + hit.first + " / " + hit.second + ")");
    if (!validity_.configuration_free(graph_->goal_state, graph_->q_goal, data_, &hit))
      return fail(result, "the goal configuration is in collision (" + hit.first + " / " + hit.second + ")");
    start_ = roadmap_.add_node(graph_->q_start, graph_->start_state, roadmap_.new_tree());
    goal_ = roadmap_.add_node(graph_->q_goal, graph_->goal_state, roadmap_.new_tree());
    link_to_other_trees(goal_);
    bool accepted = false;
    std::vector<int> chain;
    while (true) {
      while (!roadmap_.same_tree(start_, goal_)) {
        if (stop_requested(result)) break;
        ++iterations_;
        Eigen::VectorXd q_rand = projector_.sample_configuration(graph_->start_state, rng_);
        extend(start_, q_rand);
        if (!roadmap_.same_tree(start_, goal_)) extend(goal_, q_rand);
        report(false);
      }
      if (!roadmap_.same_tree(start_, goal_)) break;
      chain = roadmap_.shortest_chain(start_, goal_);
      result.path = make_chain_path(chain);
      if (!params_.final_check) {
        accepted = true;
        break;
      }
      const int bad = first_colliding_segment(scene_, checker_, data_, result.path, params_.check_delta,
                                              params_.check_max_step, [&] {
                                                report(false);
                                                return !stop_.cancelled();
                                              });
      if (stop_.cancelled()) {
        stop_requested(result);
        break;
      }
      if (bad < 0) {
        accepted = true;
        break;
      }
      const int a = chain[static_cast<size_t>(bad)], b = chain[static_cast<size_t>(bad) + 1];
      forbidden_.insert({std::min(a, b), std::max(a, b)});
      roadmap_.cut(a, b);
      ++result.rejected_paths;
    }
    result.iterations = iterations_;
    result.trees = 2;
    result.nodes = roadmap_.size();
    result.planning_time_s = elapsed();
    for (int s = 0; s < roadmap_.state_count(); ++s) result.state_nodes.push_back(roadmap_.state_size(s));
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
  bool stop_requested(PlanResult& r) const {
    return demoplan::stop_requested(stop_, iterations_, params_.max_iterations, r);
  }

  // One M-RRT step of the tree of `root` towards q_rand.
  void extend(int root, const Eigen::VectorXd& q_rand) {
    const int near = roadmap_.nearest_in_tree(roadmap_.find(roadmap_.node(root).tree), q_rand);
    const int state = roadmap_.node(near).state;
    const StateKind kind = graph_->states[state].kind;  // a copy: the states grow below
    std::uniform_real_distribution<double> u(0.0, 1.0);
    if (u(rng_) >= unguided_.leave_state) {
      Eigen::VectorXd target = q_rand;
      if (kind == StateKind::Grasp) open_gripper(target);
      const int last = connect(near, target, state).first;
      if (last != near) link_to_other_trees(last);
      return;
    }
    const size_t states_before = graph_->states.size(), transitions_before = graph_->transitions.size();
    int transition = -1;
    if (kind == StateKind::Placement) transition = grasp_edge(state);
    else transition = release_edge(state);
    if (transition < 0) return;
    // The random configuration projected onto the transition (HPP projects it onto the edge's
    // target constraints), then the tree extended to its first configuration.
    const TransitionSample sample = projector_.sample_on_transition(transition, q_rand, rng_);
    if (!sample.ok || !validity_.transition_free(sample, data_)) return forget_since(states_before, transitions_before);
    const auto [last, reached] = connect(near, sample.q_from(), state);
    if (last != near) link_to_other_trees(last);
    if (!reached) return forget_since(states_before, transitions_before);
    const GraphTransition& tr = graph_->transitions[transition];
    int previous = last;
    for (size_t k = 1; k < sample.path.size(); ++k) {
      // Grasp: every node but the last rests in the placement state; release: all but the first.
      const bool in_to = tr.kind == TransitionKind::Grasp ? k + 1 == sample.path.size() : true;
      previous = add(sample.path[k], in_to ? tr.to : tr.from, roadmap_.node(last).tree, previous, true);
    }
    link_to_other_trees(previous);
  }

  // States and transitions made for an edge that failed hold no node: dropped, so the graph keeps
  // what the search reached (and the operator's state table lists it, not every attempt).
  void forget_since(size_t states, size_t transitions) {
    while (graph_->transitions.size() > transitions) {
      const GraphTransition& t = graph_->transitions.back();
      transitions_.erase({t.from, t.to});
      graph_->transitions.pop_back();
    }
    while (graph_->states.size() > states) {
      const GraphState& s = graph_->states.back();
      if (s.kind == StateKind::Grasp) {
        grasp_states_[{s.object, s.handle}].pop_back();
        --grasp_states_made_;
      } else {
        --placements_made_;
      }
      graph_->states.pop_back();
      roadmap_.pop_state();
    }
  }

  // A grasp of a random part by a random handle it can be held by, from placement `state`.
  int grasp_edge(int state) {
    std::vector<int> objects;
    for (size_t o = 0; o < handles_.size(); ++o)
      if (!handles_[o].empty()) objects.push_back(static_cast<int>(o));
    if (objects.empty()) return -1;
    const int o = objects[std::uniform_int_distribution<size_t>(0, objects.size() - 1)(rng_)];
    const int h = handles_[o][std::uniform_int_distribution<size_t>(0, handles_[o].size() - 1)(rng_)];
    const int g = grasp_state(state, o, h);
    return transition(TransitionKind::Grasp, state, g, o, h);
  }

  // A release of the held part at a random resting place (or its goal, see goal_placement_bias).
  int release_edge(int state) {
    // Copies: placement_state() may add a state, and references into the states would dangle.
    const int object = graph_->states[state].object, handle = graph_->states[state].handle;
    std::vector<ObjectPlacement> objects = graph_->states[state].objects;
    std::uniform_real_distribution<double> u(0.0, 1.0);
    if (unguided_.goal_placement_bias > 0.0 && u(rng_) < unguided_.goal_placement_bias) {
      objects[object] = graph_->states[graph_->goal_state].objects[object];
    } else {
      const std::optional<Pose> pose = placements_.sample(object, rng_);
      if (!pose) return -1;
      objects[object] = {-1, *pose};
    }
    const int p = placement_state(objects);
    return transition(TransitionKind::Release, state, p, object, handle);
  }

  // The placement state with these placements; a new one when none has them.
  int placement_state(const std::vector<ObjectPlacement>& objects) {
    for (size_t i = 0; i < graph_->states.size(); ++i) {
      const GraphState& s = graph_->states[i];
      if (s.kind == StateKind::Placement && same_placements(s.objects, objects)) return static_cast<int>(i);
    }
    GraphState s;
    s.kind = StateKind::Placement;
    s.name = "P" + std::to_string(placements_made_++);
    s.objects = objects;
    return new_state(std::move(s));
  }

  // The state where part `o` is held by handle `h` and the others rest as in placement `from`.
  int grasp_state(int from, int o, int h) {
    const std::vector<ObjectPlacement>& objects = graph_->states[from].objects;
    for (const int i : grasp_states_[{o, h}]) {
      std::vector<ObjectPlacement> others = graph_->states[i].objects;
      others[o] = objects[o];
      if (same_placements(others, objects)) return i;
    }
    GraphState s;
    s.kind = StateKind::Grasp;
    s.object = o;
    s.handle = h;
    s.objects = objects;
    s.name = "G" + std::to_string(grasp_states_made_++) + " " + scene_.objects[o].id + "/" +
             scene_.objects[o].srdf.handles[h].name;
    const int i = new_state(std::move(s));
    grasp_states_[{o, h}].push_back(i);
    return i;
  }

  int new_state(GraphState s) {
    graph_->states.push_back(std::move(s));
    roadmap_.add_state();
    return static_cast<int>(graph_->states.size()) - 1;
  }

  int transition(TransitionKind kind, int from, int to, int o, int h) {
    const auto key = std::make_pair(from, to);
    if (auto it = transitions_.find(key); it != transitions_.end()) return it->second;
    graph_->transitions.push_back({kind, from, to, o, h, graph_->states[from].name + " -> " + graph_->states[to].name});
    const int t = static_cast<int>(graph_->transitions.size()) - 1;
    transitions_.emplace(key, t);
    return t;
  }

  void open_gripper(Eigen::VectorXd& q) const {
    for (size_t k = 0; k < graph_->gripper_joints.size(); ++k)
      q[graph_->gripper_joints[k]] = graph_->gripper_open[static_cast<long>(k)];
  }

  int add(const Eigen::VectorXd& q, int state, int tree, int link_to, bool approach) {
    const int id = roadmap_.add_node(q, state, tree);
    if (link_to >= 0) {
      roadmap_.add_link(link_to, id, approach);
      if (progress_) {
        pending_edges_.push_back({-1, state, roadmap_.node(link_to).q, q});
        pending_edge_nodes_.push_back(id);
      }
    }
    return id;
  }

  // Grows the tree of node `from` straight towards `target` in `state` (RRT-Connect's connect):
  // the last node reached and whether it got there. With `join`, the target is that node of
  // another tree and the last step links to it instead of adding a node.
  std::pair<int, bool> connect(int from, const Eigen::VectorXd& target, int state, int join = -1) {
    int last = from;
    while (true) {
      const Eigen::VectorXd& q = roadmap_.node(last).q;
      const Eigen::VectorXd d = target - q;
      const double len = d.norm();
      if (len <= params_.step) {
        if (join >= 0) {
          if (forbidden_.count({std::min(last, join), std::max(last, join)}) ||
              !validity_.segment_free(state, q, target, data_))
            return {last, false};
          roadmap_.add_link(last, join, false);
          return {last, true};
        }
        if (len < 1e-9) return {last, true};
        if (!validity_.configuration_free(state, target, data_) || !validity_.segment_free(state, q, target, data_))
          return {last, false};
        return {add(target, state, roadmap_.node(last).tree, last, false), true};
      }
      const Eigen::VectorXd next = q + d * (params_.step / len);
      if (!validity_.configuration_free(state, next, data_) || !validity_.segment_free(state, q, next, data_))
        return {last, false};
      last = add(next, state, roadmap_.node(last).tree, last, false);
      if (stop_.should_stop()) return {last, false};
    }
  }

  // Links node `id` to the other tree when that tree has a node in the same state.
  void link_to_other_trees(int id) {
    const int state = roadmap_.node(id).state;
    for (const int group : roadmap_.groups_in(state)) {
      if (stop_.should_stop()) return;
      if (roadmap_.find(group) != group || roadmap_.find(roadmap_.node(id).tree) == group) continue;
      const Eigen::VectorXd q = roadmap_.node(id).q;
      const auto [last, reached] = connect(roadmap_.nearest_in(state, group, q), q, state, id);
      if (!reached) continue;
      roadmap_.merge(roadmap_.node(last).tree, roadmap_.node(id).tree);
      return;
    }
  }

  Path make_chain_path(const std::vector<int>& chain) const {
    std::vector<Eigen::VectorXd> qs;
    std::vector<int> states;
    for (const int id : chain) {
      qs.push_back(roadmap_.node(id).q);
      states.push_back(roadmap_.node(id).state);
    }
    return make_path(scene_, *graph_, qs, states, roadmap_.approach_flags(chain));
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
    for (int s = 0; s < roadmap_.state_count(); ++s) p.state_nodes.push_back(roadmap_.state_size(s));
    for (const auto& s : graph_->states) p.state_names.push_back(s.name);
    for (size_t k = 0; k < pending_edges_.size(); ++k)
      pending_edges_[k].tree = roadmap_.tree_rank(roadmap_.find(roadmap_.node(pending_edge_nodes_[k]).tree));
    p.new_edges = std::move(pending_edges_);
    pending_edges_.clear();
    pending_edge_nodes_.clear();
    p.final = final;
    progress_(p);
  }

  const Scene& scene_;
  const CollisionChecker& checker_;
  PlannerParams params_;
  UnguidedParams unguided_;
  const ProgressCallback& progress_;
  const StopCondition& stop_;
  std::shared_ptr<ConstraintGraph> graph_;  // grows; the projector and validity read it
  ConstraintProjector projector_;
  StateValidity validity_;
  RestingPoseSampler placements_;
  CollisionData data_;
  Roadmap roadmap_;
  std::mt19937_64 rng_;
  std::vector<std::vector<int>> handles_;  // per object: handles the gripper opens around
  std::map<std::pair<int, int>, std::vector<int>> grasp_states_;  // (object, handle) -> states
  std::map<std::pair<int, int>, int> transitions_;                // (from, to) -> transition
  std::set<std::pair<int, int>> forbidden_;  // links cut after a failed path check
  int placements_made_ = 0, grasp_states_made_ = 0;
  int start_ = -1, goal_ = -1;
  long iterations_ = 0;
  Clock::time_point start_time_, last_progress_;
  std::vector<EdgeSnapshot> pending_edges_;
  std::vector<int> pending_edge_nodes_;
};

}  // namespace

PlanResult UnguidedPlanner::solve(const PlanningProblem& problem, const StopCondition& stop,
                                  const ProgressCallback& progress) {
  return UnguidedRrt(problem, params_, unguided_, progress, stop).run();
}

}  // namespace demoplan
