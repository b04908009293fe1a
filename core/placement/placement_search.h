#pragma once
// The placement search over a list of candidate base poses, on `jobs` threads, with a callback
// per finished candidate (the CLI's progress line, the GUI's heat map filling in) and a cancel
// flag checked between plans.
#include <atomic>
#include <functional>
#include <vector>

#include "core/placement/base_placement.h"

namespace demoplan {

using CandidateDone = std::function<void(const PlacementCandidate& candidate, size_t done, size_t total)>;

// Evaluates candidates[i] for every i of `indices`; the result in the order of `indices`
// (cancelled ones have screened == false). `on_done` is called from the worker threads, one
// call at a time.
std::vector<PlacementCandidate> run_placement_search(const ProblemAtBase& problem_at,
                                                     const std::vector<BasePose>& candidates,
                                                     const std::vector<int>& indices,
                                                     const PlacementSettings& settings, int jobs,
                                                     const CandidateDone& on_done = {},
                                                     const std::atomic<bool>* cancel = nullptr);

}  // namespace demoplan
