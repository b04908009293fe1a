#pragma once
// Where should the robot stand for a taught task? One candidate base pose is judged in three
// steps, each only when the one before passed: a fast screen (the start and goal configurations
// collision-free, and every pick with a handle that grasps and releases collision-free, the
// planner's own feasibility test), full planning with a few seeds (the plan job, validator
// included), and the duration of the shortest valid path's timed trajectory: the cycle time.
#include <atomic>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "core/placement/placement_region.h"
#include "core/planning/planner_settings.h"
#include "core/planning/planning_problem.h"

namespace demoplan {

struct PlacementRun {
  std::uint64_t seed = 0;
  bool valid = false;  // solved and accepted by the validator
  double planning_time_s = 0;
  double cycle_time_s = 0;  // trajectory duration, when valid
  double path_length = 0;   // robot joint-space length (rad, m), when valid
  int grasps = 0;
  std::string message;  // why not valid
};

struct PlacementCandidate {
  int index = -1;  // in the search's candidate list
  BasePose base;
  bool screened = false;  // the screen ran (false: cancelled before)
  bool feasible = false;  // the screen passed
  std::string reason;     // the screen's: the first thing that cannot be done, and why
  double screen_time_s = 0;
  std::vector<PlacementRun> runs;  // one per seed, when feasible (or when planning was forced)

  double success_rate() const;  // valid runs / runs; 0 without runs
  // The robot can stand here and do the task: it passed the screen and a plan was found.
  bool usable() const { return feasible && success_rate() > 0; }
  double median_time_s() const; // planning time over all runs; 0 without runs
  // The shortest cycle time of a valid run: the program one would export.
  std::optional<double> cycle_time_s() const;
  std::optional<double> path_length() const;  // of that run
};

struct PlacementSettings {
  PlannerSettings planner;  // seed and time limit per run; shortcutting on
  std::vector<std::uint64_t> seeds = {1, 2, 3};
  int screen_samples = 30;  // per transition
  // Plan candidates the screen rejected too (to measure how many of them planning would solve).
  bool plan_rejected = false;
};

// The planning problem with the robot standing at a base pose; throws InputError when the
// demonstration cannot be planned there.
using ProblemAtBase = std::function<PlanningProblem(const Pose& base)>;

PlacementCandidate evaluate_candidate(const ProblemAtBase& problem_at, int index, const BasePose& base,
                                      const PlacementSettings& settings, const std::atomic<bool>* cancel = nullptr);

// The screen alone: "" when the candidate passes, else the reason.
std::string screen_candidate(const PlanningProblem& problem, int samples);

// Best first: those that pass the screen, then the highest success rate, then the shortest cycle
// time, then the index (so equal candidates keep one order whichever machine or shard evaluated
// them).
void rank_candidates(std::vector<PlacementCandidate>& candidates);
// The order rank_candidates sorts by: true when `a` goes before `b`.
bool ranks_before(const PlacementCandidate& a, const PlacementCandidate& b);

}  // namespace demoplan
