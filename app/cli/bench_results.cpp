#include "app/cli/bench_results.h"

#include <algorithm>
#include <cmath>

#include "core/io/json_file.h"

namespace demoplan::cli {

namespace {

// The paper's order, then anything else in the order first seen.
const std::vector<std::string> kTaskOrder{"shelf_0", "shelf_1", "shelf_2", "tunnel_0", "waiter_0"};
const std::vector<std::string> kRobotOrder{"panda", "ur5", "kmr_iiwa"};

void add_ordered(std::vector<std::string>& list, const std::string& name) {
  if (std::find(list.begin(), list.end(), name) == list.end()) list.push_back(name);
}

void sort_by(std::vector<std::string>& list, const std::vector<std::string>& order) {
  auto rank = [&](const std::string& s) {
    const auto it = std::find(order.begin(), order.end(), s);
    return it == order.end() ? order.size() : static_cast<size_t>(it - order.begin());
  };
  std::stable_sort(list.begin(), list.end(), [&](const auto& a, const auto& b) { return rank(a) < rank(b); });
}

// The bench writes NaN as null ("-" in its table): nothing succeeded.
double number_or_nan(const JsonField& f) { return f.is_null() ? std::nan("") : f.number(); }

double quantile(std::vector<double> v, double q) {
  if (v.empty()) return std::nan("");
  std::sort(v.begin(), v.end());
  const double pos = q * static_cast<double>(v.size() - 1);
  const size_t i = static_cast<size_t>(pos);
  return i + 1 < v.size() ? v[i] + (pos - static_cast<double>(i)) * (v[i + 1] - v[i]) : v[i];
}

// Two rows of the same robot, task and planner as one.
BenchCell pooled(const BenchCell& a, const BenchCell& b) {
  if (a.solved == 0 || b.solved == 0) {
    BenchCell c = a.solved > 0 ? a : b;  // the medians of the part that solved something
    c.runs = a.runs + b.runs;
    c.solved = a.solved + b.solved;
    c.success_rate = c.runs ? static_cast<double>(c.solved) / c.runs : 0.0;
    return c;
  }
  const double wa = a.solved, wb = b.solved;
  auto mix = [&](double x, double y) { return (wa * x + wb * y) / (wa + wb); };
  BenchCell c;
  c.runs = a.runs + b.runs;
  c.solved = a.solved + b.solved;
  c.success_rate = c.runs ? static_cast<double>(c.solved) / c.runs : 0.0;
  c.median_time_s = mix(a.median_time_s, b.median_time_s);
  c.median_path_length_rad = mix(a.median_path_length_rad, b.median_path_length_rad);
  c.mean_grasps = mix(a.mean_grasps, b.mean_grasps);
  return c;
}

}  // namespace

const BenchCell* BenchResults::find(const std::string& robot, const std::string& task, const std::string& planner) const {
  const auto it = cells.find({robot, task, planner});
  return it == cells.end() ? nullptr : &it->second;
}

BenchResults read_bench_results(const std::vector<std::string>& files) {
  BenchResults out;
  out.files = files;
  // Planning times of the successful runs per (robot, task, planner), for the spread.
  std::map<std::tuple<std::string, std::string, std::string>, std::vector<double>> times;
  for (const std::string& file : files) {
    const Json doc = read_json_file(file);
    const JsonField root(doc, file);
    check_format(root, "demoplan-bench", 1, "bench result");
    const std::string from = root.has("from") ? root["from"].string() : "subgoals";
    const std::string suffix = from == "subgoals" ? "" : " (" + from + ")";
    const JsonField rows = root["rows"];
    if (rows.size() == 0) rows.fail("no rows: nothing to plot");
    // Planning times per (robot, task, planner) from the runs, for the spread. Runs written before
    // they named their planner belong to the file's planner without "+shortcut"; the shortened
    // path's times (planning + shortcutting) are not in the runs, so its bars have no spread.
    std::string base_planner;
    for (size_t i = 0; i < rows.size(); ++i) {
      const std::string p = rows[i]["planner"].string();
      if (p.find("+shortcut") == std::string::npos && base_planner.empty()) base_planner = p;
    }
    if (root.has("runs")) {
      const JsonField runs = root["runs"];
      for (size_t i = 0; i < runs.size(); ++i) {
        const JsonField r = runs[i];
        const std::string planner = r.has("planner") ? r["planner"].string() : base_planner;
        const bool ok = r["solved"].boolean() && r["valid"].boolean();
        const double t = r["planning_time_s"].number();
        if (ok) times[{r["robot"].string(), r["task"].string(), planner + suffix}].push_back(t);
        ++out.runs;
      }
    }
    for (size_t i = 0; i < rows.size(); ++i) {
      const JsonField row = rows[i];
      const std::string robot = row["robot"].string(), task = row["task"].string();
      const std::string planner = row["planner"].string();
      BenchCell c;
      c.success_rate = row["success_rate"].number();
      if (c.success_rate < 0 || c.success_rate > 1) row["success_rate"].fail("must be between 0 and 1");
      c.runs = row["runs"].integer();
      c.median_time_s = number_or_nan(row["median_time_s"]);
      c.median_path_length_rad = number_or_nan(row["median_path_length_rad"]);
      c.mean_grasps = number_or_nan(row["mean_grasps"]);
      c.solved = row["solved"].integer();
      const std::string name = planner + suffix;
      if (auto it = out.cells.find({robot, task, name}); it != out.cells.end()) {
        // The same instance set run in parts (e.g. the base poses that cannot be done, apart):
        // pooled. Medians cannot be pooled from rows; when both parts solved something, the
        // figure shows their mean weighted by solved runs and says so.
        if (it->second.solved > 0 && c.solved > 0)
          out.notes.push_back(file + ": rows[" + std::to_string(i) + "]: " + task + " " + robot + " " + name +
                              " again: its medians are averaged with the earlier row's, weighted by solved runs");
        c = pooled(it->second, c);
      }
      out.cells[{robot, task, name}] = c;
      add_ordered(out.robots, robot);
      add_ordered(out.tasks, task);
      add_ordered(out.planners, name);
    }
  }
  for (auto& [key, c] : out.cells) {
    const auto t = times.find(key);
    c.time_q1_s = t == times.end() ? std::nan("") : quantile(t->second, 0.25);
    c.time_q3_s = t == times.end() ? std::nan("") : quantile(t->second, 0.75);
  }
  sort_by(out.robots, kRobotOrder);
  sort_by(out.tasks, kTaskOrder);
  // A planner next to its shortened variant, in the order first seen.
  std::vector<std::string> planners;
  for (const std::string& p : out.planners)
    if (p.find("+shortcut") == std::string::npos) {
      add_ordered(planners, p);
      std::string sc = p;
      const size_t paren = sc.find(" (");
      sc.insert(paren == std::string::npos ? sc.size() : paren, "+shortcut");
      if (std::find(out.planners.begin(), out.planners.end(), sc) != out.planners.end()) add_ordered(planners, sc);
    }
  for (const std::string& p : out.planners) add_ordered(planners, p);
  out.planners = planners;
  return out;
}

}  // namespace demoplan::cli
