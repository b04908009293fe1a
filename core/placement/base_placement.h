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

#include "core/placement/placement_candidate.h"
#include "core/placement/placement_region.h"
#include "core/planning/planner_settings.h"
#include "core/planning/planning_problem.h"

namespace demoplan {

struct PlacementSettings {
  // Seed and time limit per run; shortcutting on, ended by its counts (failures, attempts,
  // detour rounds), never by the clock: its time limits are ignored.
  PlannerSettings planner;
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

}  // namespace demoplan
