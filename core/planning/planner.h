#pragma once
// What every planner offers (OMPL's base::Planner): solve a PlanningProblem until it is solved
// or the StopCondition says stop, reporting progress on the way. The guided planner is one
// implementation (guided_planner.h); planner_registry.h finds them by name.
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "core/path/path.h"
#include "core/planning/planning_problem.h"
#include "core/planning/stop_condition.h"

namespace demoplan {

// The parameters of our sampling planners: the seed, the time limit the plan job turns into
// its StopCondition, and the guided planner's own.
struct PlannerParams {
  double eta_sample_tree = 0.1;  // probability of rooting a new tree at a sampled transition
  double step = 0.3;             // delta: tree growth step, joint-space Euclidean (rad, m)
  // Edges are collision-checked every this much: half the validator's 0.01, so a validator
  // sample is never more than 0.0025 rad from a checked one.
  double resolution = 0.005;
  long max_iterations = 10'000'000;
  double time_limit = 60.0;      // s, wall clock
  std::uint64_t seed = 1;
  double progress_period = 0.05;  // s between progress callbacks
  // Beyond the paper: draw transitions with weight 1 / (1 + collision-free samples they already
  // gave) instead of uniformly, and seed a transition's projection from a node of its source
  // state this often.
  bool balance_transitions = true;
  double seed_from_trees = 0.5;
  // Weight, relative to 1, of growing in a state whose nodes all belong to one tree (1: the
  // paper's uniform choice); what it takes from growth goes to sampling trees.
  double lone_tree_weight = 0.05;
  // A transition sample whose first configuration is this close to a root the transition has
  // already is not made a tree again (a 6-joint arm meets a handle in at most 8 ways).
  double same_root = 1e-3;
  // Beyond the paper: a found path is collision-checked again where the benchmark samples it
  // (t = k * check_delta along its length, plus enough points that no two are more than
  // check_max_step apart): between the edges' samples a held object can clip an obstacle edge.
  // A segment that fails is cut from the trees, never made again, and planning goes on.
  bool final_check = true;
  double check_delta = 0.001;
  double check_max_step = 0.01;
  // Beyond the paper (guided planner, regrasp.h): after regrasp_after iterations without a path
  // (0: never), the picks where the search stalls get regrasp placements the demonstration does
  // not show. The demonstrated search goes on; regrasp_candidates variants, each the
  // demonstration with one regrasp, are searched beside it (per round the demonstrated search
  // gets regrasp_slice iterations, the variants as many together), and a variant that has had
  // regrasp_budget iterations gives its place to a new placement. Paths found within
  // regrasp_after iterations are exactly those found without it.
  long regrasp_after = 10'000;
  int regrasp_candidates = 4;
  long regrasp_slice = 1'000;
  long regrasp_budget = 6'000;
  // Guided planner, beyond the paper: lazy edges (LazyRRT). A new node's configuration is
  // checked, the link to it only when a found path uses it; a link that fails is cut as after a
  // failed final check.
  // Most links never lie on a found path: median planning time 0.35-0.71x of checking every
  // link when it is made (docs/benchmarks.md). Where obstacles are close that turns round:
  // trees grow through walls and every path found is cut again. A search whose found paths
  // have used lazy_rejections colliding links makes its further links checked.
  bool lazy_edges = true;
  int lazy_rejections = 10;
};

// One edge added since the previous snapshot, for drawing the trees grow.
struct EdgeSnapshot {
  int tree = -1;  // index into PlannerProgress::tree_nodes
  int state = -1;
  Eigen::VectorXd from, to;
};

struct PlannerProgress {
  double elapsed_s = 0.0;
  long iterations = 0;
  int trees = 0;                       // trees left after merging
  size_t nodes = 0;
  std::vector<size_t> tree_nodes;      // per current tree
  std::vector<size_t> state_nodes;     // per graph state
  // The names of those states when the planner makes its own (unguided); empty: the problem's.
  std::vector<std::string> state_names;
  int rejected_paths = 0;  // found paths the final check rejected (see PlannerParams::final_check)
  std::vector<EdgeSnapshot> new_edges; // since the previous snapshot
  std::vector<std::pair<int, Eigen::VectorXd>> new_roots;  // (state, q) of new transition trees
  bool final = false;
};

using ProgressCallback = std::function<void(const PlannerProgress&)>;

struct PlanResult {
  bool solved = false;
  bool cancelled = false;
  std::string message;  // why not solved, when not
  Path path;            // start to goal, unshortened
  long iterations = 0;
  int trees = 0;        // trees ever created
  size_t nodes = 0;
  double planning_time_s = 0.0;
  std::vector<size_t> state_nodes;
  int rejected_paths = 0;  // found paths the final check rejected (see PlannerParams::final_check)
  int rejected_links = 0;  // lazy links a found path used that collide (PlannerParams::lazy_edges)
  // Transitions never sampled collision-free: for "which transition could not be sampled".
  std::vector<std::string> unsampled_transitions;
  // The graph whose states path.waypoints[k].state indexes when the planner made its own (the
  // unguided planner discovers its placements); null: the problem's.
  std::shared_ptr<const ConstraintGraph> graph;
  // The regrasp the guided planner added to the demonstration to find the path (regrasp.h),
  // e.g. "pick 2 (YCBV_03): put down at (0.310, -0.120, 0.797) m and taken again"; empty: none.
  std::string regrasp;
};

// Whether a sampling planner must stop after `iterations`: cancelled (sets r.cancelled), the
// iteration limit or the time limit; r.message then says which.
bool stop_requested(const StopCondition& stop, long iterations, long max_iterations, PlanResult& r);

class Planner {
public:
  virtual ~Planner() = default;
  // The name it is registered under, e.g. "guided".
  virtual std::string name() const = 0;
  // The same problem, parameters and seed give the same path, bit for bit, unless `stop` ends
  // the search. `stop` is polled at least every few ms.
  virtual PlanResult solve(const PlanningProblem& problem, const StopCondition& stop,
                           const ProgressCallback& progress = {}) = 0;
};

}  // namespace demoplan
