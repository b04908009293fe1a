#pragma once
// The file `demoplan-cli bench --out` writes (format "demoplan-bench", version 1): what was run
// (the arguments that define the run list), every run, and the table of the paper's Fig. 4
// computed from the runs. A benchmark spread over a cluster (bench --shard I/N) writes one file
// per shard; merge joins them into the file one unsharded run writes.
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/validation/path_validator.h"

namespace demoplan::cli {

inline constexpr const char* kBenchFormat = "demoplan-bench";

struct BenchRun {
  size_t index = 0;  // in the whole benchmark's run list
  std::string planner, task, robot;
  int pose = 0, seed = 0;
  double time_limit = 60;
  // Results, for the planner's own path and for the shortened one.
  bool solved = false;
  bool feasible = true;  // false: the instance's picks cannot all be done from its base pose
  double time_s = 0;
  long iterations = 0;
  int trees = 0;
  size_t nodes = 0;
  std::string message;  // the planner's, when not solved
  std::string regrasp;  // the regrasp the planner added, if any
  ValidationReport raw, shortened;
  double shortcut_s = 0;
};

// One row per task, robot and planner (its own path and "+shortcut"), and each planner's median
// planning time against the first planner's, per task and robot.
struct BenchTable {
  nlohmann::json rows = nlohmann::json::array(), comparisons = nlohmann::json::array();
};
BenchTable tabulate_bench_runs(const std::vector<BenchRun>& runs, const std::vector<std::string>& planners);
// The table as bench prints it on stderr.
void print_bench_table(const BenchTable& table);

struct BenchFile {
  // What defines the run list and the settings (tasks or cell, robots, poses, seeds, planners,
  // time limits, ...): the same in every shard of one benchmark, and what merge checks. Has
  // "planners", the planners in the table's order.
  nlohmann::json arguments;
  size_t run_count = 0;       // in the whole benchmark
  int shard = 1, shards = 1;  // 1 of 1: every run
  std::vector<BenchRun> runs;  // in run list order

  std::vector<std::string> planners() const { return arguments.at("planners").get<std::vector<std::string>>(); }
};

void save_bench_file(const std::string& file, const BenchFile& bench, const BenchTable& table);
// Joins the shards of one benchmark (every shard 1..N exactly once, the same arguments and run
// count) into the whole run list. Throws InputError naming the file and field that do not fit.
BenchFile merge_bench_files(const std::vector<std::string>& files);

}  // namespace demoplan::cli
