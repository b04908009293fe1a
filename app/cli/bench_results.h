#pragma once
// The results `demoplan-cli bench --out` writes, read back for the figure: one cell per robot,
// task and planner with the four numbers of the paper's Fig. 4, the planning times' spread from
// the per-run records. No Qt: plotting is the caller's.
#include <map>
#include <string>
#include <tuple>
#include <vector>

namespace demoplan::cli {

struct BenchCell {
  double success_rate = 0;  // 0..1, success = solved and valid
  double median_time_s = 0, time_q1_s = 0, time_q3_s = 0;  // NaN when nothing succeeded / no runs
  double median_path_length_rad = 0;
  double mean_grasps = 0;
  int runs = 0, solved = 0;
};

struct BenchResults {
  std::vector<std::string> files;
  std::vector<std::string> robots, tasks, planners;  // in display order
  std::map<std::tuple<std::string, std::string, std::string>, BenchCell> cells;  // (robot, task, planner)
  size_t runs = 0;                                   // per-run records read
  std::vector<std::string> notes;                    // e.g. a cell given by two files
  const BenchCell* find(const std::string& robot, const std::string& task, const std::string& planner) const;
};

// Reads demoplan-bench files (version 1). A planner's rows from a file made with another `from`
// than "subgoals" are named "<planner> (<from>)". Rows of the same robot, task and planner (a
// benchmark run in parts, in one file or several) are pooled. Throws InputError naming the file
// and field.
BenchResults read_bench_results(const std::vector<std::string>& files);

}  // namespace demoplan::cli
