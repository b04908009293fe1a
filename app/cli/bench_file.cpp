#include "app/cli/bench_file.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <map>
#include <sstream>
#include <tuple>

#include "app/cli/run_statistics.h"
#include "core/error.h"
#include "core/io/json_file.h"
#include "core/io/shards.h"

namespace demoplan::cli {

namespace {

constexpr int kBenchVersion = 1;
constexpr const char* kCountKey = "run_count";

nlohmann::json run_json(const BenchRun& r) {
  nlohmann::json j{{"index", r.index},
                   {"planner", r.planner},
                   {"task", r.task},
                   {"robot", r.robot},
                   {"pose", r.pose},
                   {"seed", r.seed},
                   {"time_limit_s", r.time_limit},
                   {"solved", r.solved},
                   {"valid", r.solved && r.raw.valid},
                   {"message", r.solved ? r.raw.message : r.message},
                   {"feasible", r.feasible},
                   {"planning_time_s", r.time_s},
                   {"iterations", r.iterations},
                   {"trees", r.trees},
                   {"nodes", r.nodes},
                   {"path_length_rad", r.raw.length.robot},
                   {"grasps", r.raw.grasps},
                   {"gripper_closes", r.raw.gripper_closes},
                   {"shortened_valid", r.solved && r.shortened.valid},
                   {"shortened_path_length_rad", r.shortened.length.robot},
                   {"shortened_grasps", r.shortened.grasps},
                   {"shortened_gripper_closes", r.shortened.gripper_closes},
                   {"shortcut_time_s", r.shortcut_s}};
  if (!r.regrasp.empty()) j["regrasp"] = r.regrasp;
  return j;
}

// What the table needs of a run, and what merge writes back.
BenchRun read_run(const JsonField& j, size_t run_count) {
  BenchRun r;
  r.index = static_cast<size_t>(item_index(j["index"], static_cast<int>(run_count)));
  r.planner = j["planner"].string(), r.task = j["task"].string(), r.robot = j["robot"].string();
  r.pose = j["pose"].integer(), r.seed = j["seed"].integer();
  r.time_limit = j["time_limit_s"].number();
  r.solved = j["solved"].boolean();
  (r.solved ? r.raw.message : r.message) = j["message"].string();
  r.feasible = j["feasible"].boolean();
  r.time_s = j["planning_time_s"].number();
  r.iterations = static_cast<long>(j["iterations"].number());
  r.trees = j["trees"].integer();
  r.nodes = static_cast<size_t>(j["nodes"].number());
  r.raw.valid = j["valid"].boolean();
  r.raw.length.robot = j["path_length_rad"].number();
  r.raw.grasps = j["grasps"].integer();
  // Files written before gripper_closes was recorded: the benchmark's count stands in.
  r.raw.gripper_closes = j.has("gripper_closes") ? j["gripper_closes"].integer() : r.raw.grasps;
  r.shortened.valid = j["shortened_valid"].boolean();
  r.shortened.length.robot = j["shortened_path_length_rad"].number();
  r.shortened.grasps = j["shortened_grasps"].integer();
  r.shortened.gripper_closes =
      j.has("shortened_gripper_closes") ? j["shortened_gripper_closes"].integer() : r.shortened.grasps;
  r.shortcut_s = j["shortcut_time_s"].number();
  if (j.has("regrasp")) r.regrasp = j["regrasp"].string();
  return r;
}

BenchFile load_bench_file(const std::string& file) {
  const Json json = read_json_file(file);
  const JsonField root(json, file);
  check_format(root, kBenchFormat, kBenchVersion, "bench result");
  if (!root.has("arguments"))
    throw InputError(file, "arguments", "missing: written by a bench from before --shard, it cannot be merged");
  BenchFile b;
  const ShardHeader header = read_shard_header(root, kCountKey);
  b.arguments = header.arguments;
  const JsonField planners = root["arguments"]["planners"];
  for (size_t i = 0; i < planners.size(); ++i) planners[i].string();  // read by BenchFile::planners()
  b.run_count = static_cast<size_t>(header.items);
  b.shard = header.shard, b.shards = header.shards;
  const JsonField runs = root["runs"];
  for (size_t i = 0; i < runs.size(); ++i) b.runs.push_back(read_run(runs[i], b.run_count));
  return b;
}

}  // namespace

BenchTable tabulate_bench_runs(const std::vector<BenchRun>& runs, const std::vector<std::string>& planners) {
  BenchTable table;
  std::map<std::pair<std::string, std::string>, std::vector<const BenchRun*>> groups;
  for (const BenchRun& r : runs) groups[{r.task, r.robot}].push_back(&r);
  // Median planning times (own path) per (task, robot, planner), for the ratios.
  std::map<std::tuple<std::string, std::string, std::string>, double> medians;
  for (const auto& [key, all_group] : groups)
    for (const std::string& planner : planners)
      for (const bool shortened : {false, true}) {
        std::vector<const BenchRun*> group;
        for (const BenchRun* r : all_group)
          if (r->planner == planner) group.push_back(r);
        if (group.empty()) continue;  // a shard may hold none of this planner's runs here
        std::vector<double> times, lengths, grasps;
        int solved = 0, feasible = 0;
        for (const BenchRun* r : group) {
          if (r->feasible) ++feasible;
          const ValidationReport& v = shortened ? r->shortened : r->raw;
          if (!r->solved || !v.valid) continue;  // success = solved and valid
          ++solved;
          times.push_back(r->time_s + (shortened ? r->shortcut_s : 0.0));
          lengths.push_back(v.length.robot);
          grasps.push_back(v.grasps);
        }
        if (!shortened) medians[{key.first, key.second, planner}] = median(times);
        const double rate = static_cast<double>(solved) / static_cast<double>(group.size());
        const double feasible_rate = feasible ? static_cast<double>(solved) / feasible : std::nan("");
        table.rows.push_back({{"task", key.first}, {"robot", key.second},
                              {"planner", shortened ? planner + "+shortcut" : planner},
                              {"runs", group.size()}, {"solved", solved}, {"success_rate", rate},
                              {"feasible_runs", feasible}, {"success_rate_feasible", feasible_rate},
                              {"median_time_s", median(times)}, {"mean_time_s", mean(times)},
                              {"median_path_length_rad", median(lengths)}, {"mean_grasps", mean(grasps)}});
      }
  // Each planner against the first: ratio of median planning times where both solved something.
  auto median_of = [&](const std::string& task, const std::string& robot, const std::string& planner) {
    const auto it = medians.find({task, robot, planner});
    return it == medians.end() ? std::nan("") : it->second;
  };
  for (size_t p = 1; p < planners.size(); ++p)
    for (const auto& [key, group] : groups) {
      // NaN when either solved nothing
      const double ratio = median_of(key.first, key.second, planners[p]) / median_of(key.first, key.second, planners[0]);
      table.comparisons.push_back({{"task", key.first}, {"robot", key.second}, {"planner", planners[p]},
                                   {"baseline", planners[0]},
                                   {"median_time_ratio", std::isnan(ratio) ? nlohmann::json() : nlohmann::json(ratio)}});
    }
  return table;
}

void print_bench_table(const BenchTable& table) {
  // A figure over no runs (nothing solved, no feasible instance) is printed as "-".
  auto cell = [](double v, int width, const char* unit = "") {
    std::ostringstream c;
    if (std::isnan(v)) c << "-";
    else c << std::fixed << std::setprecision(2) << v << unit;
    return (std::ostringstream() << std::setw(width) << c.str()).str();
  };
  std::cerr << "\n" << std::left << std::setw(10) << "task" << std::setw(10) << "robot" << std::setw(17) << "planner"
            << std::right << std::setw(6) << "runs" << std::setw(9) << "feasible" << std::setw(9) << "success"
            << std::setw(10) << "of feas." << std::setw(10) << "median s"
            << std::setw(9) << "mean s" << std::setw(12) << "length rad" << std::setw(8) << "grasps" << "\n";
  for (const auto& row : table.rows) {
    auto number = [&](const char* key) { return row[key].get<double>(); };
    std::cerr << std::left << std::setw(10) << row["task"].get<std::string>() << std::setw(10)
              << row["robot"].get<std::string>() << std::setw(17) << row["planner"].get<std::string>() << std::right
              << std::setw(6) << row["runs"].get<size_t>() << std::setw(9) << row["feasible_runs"].get<int>()
              << cell(number("success_rate") * 100, 9, "%") << cell(number("success_rate_feasible") * 100, 10, "%")
              << cell(number("median_time_s"), 10) << cell(number("mean_time_s"), 9)
              << cell(number("median_path_length_rad"), 12) << cell(number("mean_grasps"), 8) << "\n";
  }
  std::string planner;
  for (const auto& c : table.comparisons) {
    if (c["planner"] != planner) {
      planner = c["planner"].get<std::string>();
      std::cerr << "\nmedian planning time, " << planner << " / " << c["baseline"].get<std::string>() << ":\n";
    }
    const nlohmann::json& ratio = c["median_time_ratio"];
    std::cerr << "  " << std::left << std::setw(10) << c["task"].get<std::string>() << std::setw(10)
              << c["robot"].get<std::string>() << std::right << (ratio.is_null() ? "-" : cell(ratio.get<double>(), 0))
              << "\n";
  }
}

void save_bench_file(const std::string& file, const BenchFile& bench, const BenchTable& table) {
  nlohmann::json runs = nlohmann::json::array();
  for (const BenchRun& r : bench.runs) runs.push_back(run_json(r));
  nlohmann::json j{{"format", kBenchFormat},
                   {"version", kBenchVersion},
                   {"rows", table.rows},
                   {"comparisons", table.comparisons},
                   {"runs", runs}};
  write_shard_header(j, {bench.arguments, static_cast<int>(bench.run_count), bench.shard, bench.shards}, kCountKey);
  // As before "arguments": how the tasks were made (figure reads "from").
  for (const char* key : {"from", "handles", "cell", "demos"})
    if (bench.arguments.contains(key)) j[key] = bench.arguments[key];
  write_json_file_atomic(file, j);
}

BenchFile merge_bench_files(const std::vector<std::string>& files) {
  BenchFile out;
  ShardJoin join("benchmark");
  for (const std::string& file : files) {
    BenchFile part = load_bench_file(file);
    join.add(file, {part.arguments, static_cast<int>(part.run_count), part.shard, part.shards});
    for (BenchRun& r : part.runs) {
      join.claim(file, static_cast<int>(r.index), "runs");
      out.runs.push_back(std::move(r));
    }
  }
  join.finish("runs");
  out.arguments = join.header().arguments;
  out.run_count = static_cast<size_t>(join.header().items);
  std::sort(out.runs.begin(), out.runs.end(), [](const BenchRun& a, const BenchRun& b) { return a.index < b.index; });
  // An instance is assessed in every shard where one of its runs failed, with the same answer;
  // a shard whose runs of it all succeeded did not ask. One unsharded run applies the answer to
  // every run of the instance: so does the merge.
  std::map<std::tuple<std::string, std::string, int>, bool> feasible;
  for (const BenchRun& r : out.runs) {
    bool& all = feasible.try_emplace({r.task, r.robot, r.pose}, true).first->second;
    all = all && r.feasible;
  }
  for (BenchRun& r : out.runs) r.feasible = feasible.at({r.task, r.robot, r.pose});
  out.shard = out.shards = 1;
  return out;
}

}  // namespace demoplan::cli
