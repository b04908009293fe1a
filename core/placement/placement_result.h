#pragma once
// The placement search's result file (docs/placement.md): what was searched, which slice of the
// candidates this file holds (a shard of a search spread over a cluster, or all of them), and
// every evaluated candidate. Partial results of one search merge into the result one unsharded
// run would give.
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/placement/placement_candidate.h"
#include "core/placement/furniture_footprints.h"

namespace demoplan {

struct PlacementResult {
  // What was searched (task or cell, region, samples, seeds, planner settings): the same in every
  // shard of one search, and what merge checks.
  nlohmann::json arguments;
  int candidate_count = 0;  // in the whole search
  int shard = 1, shards = 1;  // 1 of 1: every candidate
  std::vector<PlacementCandidate> candidates;  // ranked in a complete result
  // The task's published base poses judged alike, for comparison (index: the pose id); only the
  // first shard evaluates them.
  std::vector<PlacementCandidate> published;
  std::vector<Footprint> furniture;  // what stands in the region, for the heat map
  double wall_time_s = 0;  // the run's; a merged result: the longest shard's
  bool cancelled = false;

  bool complete() const { return shards == 1; }
  int feasible_count() const;
  // For a complete result: why there is no plan, when no candidate has one; "" otherwise.
  std::string message() const;
};

nlohmann::json placement_result_json(const PlacementResult& result);
void save_placement_result(const std::string& file, const PlacementResult& result);
// Throws InputError naming the file and field.
PlacementResult load_placement_result(const std::string& file);

// Joins the shards of one search (every shard 1..N exactly once, the same arguments and
// candidate count) and ranks them. Throws InputError naming the file that does not fit.
PlacementResult merge_placement_results(const std::vector<std::string>& files);

}  // namespace demoplan
