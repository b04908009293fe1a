// demoplan-cli bench: the paper's benchmark protocol over tasks, robots, base poses and seeds;
// every found path is checked by the validator. Prints the columns of the paper's Fig. 4.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <map>
#include <memory>
#include <mutex>
#include <numeric>
#include <sstream>
#include <thread>
#include <unistd.h>

#include <nlohmann/json.hpp>

#include "app/cli/command.h"
#include "app/cli/run_statistics.h"
#include "app/cli/list_options.h"
#include "app/cli/task_inputs.h"
#include "core/demo/benchmark_demonstration.h"
#include "core/error.h"
#include "core/io/json_file.h"
#include "core/project/benchmark_instance.h"
#include "core/planning/plan_job.h"
#include "core/planning/planner_registry.h"

namespace demoplan::cli {

namespace {

struct BenchOptions {
  std::string tasks = "shelf_0,shelf_1,shelf_2,tunnel_0,waiter_0";
  std::string robots = "panda,ur5,kmr_iiwa";
  std::string poses = "0-4";
  std::string seeds = "1-10";
  double time_limit = 60.0;
  double waiter_time_limit = 300.0;
  std::string from = "subgoals";
  std::string handles = "srdf";
  std::string planner = "guided";
  std::string compare;  // planners run alternately on the same runs, e.g. "guided,unguided"
  int jobs = 1;
  std::string cell, demos;  // a cell and its demonstrations in place of tasks, robots and poses
  std::string out, ompl_log, data_dir;
  bool json = false;
};

struct Run {
  std::string planner;
  std::string task, robot;
  int pose = 0, seed = 0;
  double time_limit = 60;
  // Results, for the planner's own path and for the shortened one.
  bool solved = false;
  double time_s = 0;
  long iterations = 0;
  int trees = 0;
  size_t nodes = 0;
  std::string message;
  std::string regrasp;  // the regrasp the planner added, if any
  ValidationReport raw, shortened;
  double shortcut_s = 0;
};

struct Instance {
  PlanningProblem problem;
  // After the first failed run: can every pick be done from this base pose at all?
  std::once_flag assessed;
  bool infeasible = false;
  std::string infeasible_reason;
};


// One experiment (a task and robot); per planner two OMPL planners, its own path and shortened.
void write_ompl_log(const std::string& file, const std::string& experiment, const std::vector<std::string>& planners,
                    const std::vector<const Run*>& all_runs, double time_limit, double total_s) {
  std::ofstream out(file);
  if (!out) throw InputError(file, "", "cannot write the OMPL log");
  char host[256] = "localhost";
  gethostname(host, sizeof(host) - 1);
  const std::time_t now = std::time(nullptr);
  out << "demoplan version 0.1.0\nExperiment " << experiment << "\n0 experiment properties\nRunning on " << host
      << "\nStarting at " << std::put_time(std::localtime(&now), "%Y-%m-%d %H:%M:%S")
      << "\n<<<|\nvideo-guided multi-contact RRT on the guided-TAMP benchmark\n|>>>\n<<<|\n|>>>\n"
      << (all_runs.empty() ? 0 : all_runs.front()->seed) << " is the random seed\n"
      << time_limit << " seconds per run\n0 MB per run\n" << all_runs.size() / planners.size() << " runs per planner\n"
      << total_s << " seconds spent to collect the data\n0 enum types\n" << 2 * planners.size() << " planners\n";
  for (int k = 0; k < 2 * static_cast<int>(planners.size()); ++k) {
    const int planner = k % 2;
    const std::string& name = planners[static_cast<size_t>(k / 2)];
    std::vector<const Run*> runs;
    for (const Run* r : all_runs)
      if (r->planner == name) runs.push_back(r);
    out << (planner == 0 ? name : name + "+shortcut") << "\n0 common properties\n"
        << "9 properties for each run\ntime REAL\nsolved BOOLEAN\ncorrect solution BOOLEAN\nsolution length REAL\n"
           "object translation REAL\nobject rotation REAL\ngrasps INTEGER\ngraph states INTEGER\nseed INTEGER\n"
        << runs.size() << " runs\n";
    for (const Run* r : runs) {
      const ValidationReport& v = planner == 0 ? r->raw : r->shortened;
      out << (r->time_s + (planner == 1 ? r->shortcut_s : 0.0)) << "; " << r->solved << "; " << (r->solved && v.valid)
          << "; ";
      if (r->solved) out << v.length.robot << "; " << v.length.object_translation << "; " << v.length.object_rotation << "; " << v.grasps;
      else out << "; ; ; ";
      out << "; " << r->nodes << "; " << r->seed << "; \n";
    }
    out << ".\n";
  }
}

int run_bench(const BenchOptions& o) {
  const auto t0 = std::chrono::steady_clock::now();
  const std::vector<int> poses = int_range(o.poses, "--poses"), seeds = int_range(o.seeds, "--seeds");
  const std::vector<std::string> planners = o.compare.empty() ? std::vector<std::string>{o.planner} : split_list(o.compare);
  std::map<std::tuple<std::string, std::string, int>, std::unique_ptr<Instance>> instances;
  std::vector<Run> runs;
  MeshCache meshes;  // every instance of a robot or task loads the same mesh files
  auto add_runs = [&](const std::string& task, const std::string& robot, int pose, double time_limit) {
    // Planners alternate on each seed, so a slow phase of the machine hits them alike.
    for (int seed : seeds)
      for (const std::string& planner : planners) {
        Run& r = runs.emplace_back();
        r.planner = planner, r.task = task, r.robot = robot, r.pose = pose, r.seed = seed;
        r.time_limit = time_limit;
      }
  };
  if (!o.cell.empty()) {
    // A cell: one instance per demonstration, named by its file.
    if (o.demos.empty()) throw InputError(o.cell, "", "a cell needs demonstrations: give --demos");
    const auto scene = load_cell_scene(o.cell, o.data_dir);
    for (const auto& demo : split_list(o.demos)) {
      const std::string name = std::filesystem::path(demo).stem().string();
      if (instances.count({name, scene->robot.name, 0}))
        throw InputError(demo, "--demos", "two demonstrations are named '" + name + "': rename one");
      auto in = std::make_unique<Instance>();
      in->problem = cell_task_instance(scene, demo).problem;
      instances[{name, scene->robot.name, 0}] = std::move(in);
      add_runs(name, scene->robot.name, 0, o.time_limit);
    }
  }
  for (const auto& task_name : o.cell.empty() ? split_list(o.tasks) : std::vector<std::string>{}) {
    const BenchmarkTask task = load_benchmark_task(o.data_dir, task_name);
    for (const auto& robot : split_list(o.robots)) {
      const std::vector<int> available = benchmark_pose_ids(task, robot);
      for (int pose : poses) {
        if (std::find(available.begin(), available.end(), pose) == available.end()) continue;
        auto scene = benchmark_scene_with_handles(task, robot, pose, o.handles, &meshes);
        auto in = std::make_unique<Instance>();
        in->problem = make_task_instance(task, scene, o.from).problem;
        instances[{task_name, robot, pose}] = std::move(in);
        add_runs(task_name, robot, pose, task.task_name == "waiter" ? o.waiter_time_limit : o.time_limit);
      }
    }
  }
  std::cerr << runs.size() << " runs on " << instances.size() << " task instances, " << o.jobs << " job(s)\n";
  std::mutex mutex;
  size_t next = 0, done = 0;
  auto worker = [&] {
    while (true) {
      size_t i;
      {
        std::lock_guard lock(mutex);
        if (next >= runs.size()) return;
        i = next++;
      }
      Run& r = runs[i];
      Instance& in = *instances.at({r.task, r.robot, r.pose});
      PlannerSettings settings;
      settings.planner_name = r.planner;
      settings.planner.seed = static_cast<std::uint64_t>(r.seed);
      settings.planner.time_limit = r.time_limit;
      const PlanReport s = run_plan_job(in.problem, settings, {}, nullptr, {.assess_on_failure = false});
      r.solved = s.plan.solved;
      r.time_s = s.plan.planning_time_s;
      r.iterations = s.plan.iterations;
      r.trees = s.plan.trees;
      r.nodes = s.plan.nodes;
      r.message = s.plan.message;
      r.regrasp = s.plan.regrasp;
      if (!r.solved)
        std::call_once(in.assessed, [&] {
          PlannerSettings once = settings;
          once.planner.seed = 1;  // the same answer whichever run fails first
          const FeasibilityReport f = assess_problem(in.problem, once);
          in.infeasible = !f.feasible();
          in.infeasible_reason = f.summary(*in.problem.scene);
        });
      if (r.solved) {
        r.raw = s.planner_validation;
        r.shortcut_s = s.shortcut.time_s;
        r.shortened = s.validation;  // the planner's own path when the shortened one was dropped
      }
      std::lock_guard lock(mutex);
      ++done;
      std::cerr << "[" << done << "/" << runs.size() << "] " << r.task << " " << r.robot << " pose " << r.pose
                << " seed " << r.seed << (planners.size() > 1 ? " " + r.planner : "") << ": "
                << (r.solved ? (r.raw.valid ? "valid" : "INVALID (" + r.raw.message + ")") : "not solved (" + r.message + ")")
                << ", " << std::fixed << std::setprecision(2) << r.time_s << " s\n" << std::defaultfloat;
      if (!r.solved && in.infeasible) std::cerr << "    infeasible: " << in.infeasible_reason;
    }
  };
  std::vector<std::thread> pool;
  for (int j = 0; j < std::max(1, o.jobs); ++j) pool.emplace_back(worker);
  for (auto& t : pool) t.join();
  const double total_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();

  // One row per task, robot and planner.
  nlohmann::json rows = nlohmann::json::array();
  std::map<std::pair<std::string, std::string>, std::vector<const Run*>> groups;
  for (const Run& r : runs) groups[{r.task, r.robot}].push_back(&r);
  std::cerr << "\n" << std::left << std::setw(10) << "task" << std::setw(10) << "robot" << std::setw(17) << "planner"
            << std::right << std::setw(6) << "runs" << std::setw(9) << "feasible" << std::setw(9) << "success"
            << std::setw(10) << "of feas." << std::setw(10) << "median s"
            << std::setw(9) << "mean s" << std::setw(12) << "length rad" << std::setw(8) << "grasps" << "\n";
  // Median planning times (own path) per (task, robot, planner), for the ratios.
  std::map<std::tuple<std::string, std::string, std::string>, double> medians;
  for (const auto& [key, all_group] : groups) {
    for (int k = 0; k < 2 * static_cast<int>(planners.size()); ++k) {
      const int planner = k % 2;
      const std::string& planner_name = planners[static_cast<size_t>(k / 2)];
      std::vector<const Run*> group;
      for (const Run* r : all_group)
        if (r->planner == planner_name) group.push_back(r);
      std::vector<double> times, lengths, grasps;
      int solved = 0, feasible = 0;
      for (const Run* r : group) {
        if (!instances.at({r->task, r->robot, r->pose})->infeasible) ++feasible;
        const ValidationReport& v = planner == 0 ? r->raw : r->shortened;
        if (!r->solved || !v.valid) continue;  // success = solved and valid
        ++solved;
        times.push_back(r->time_s + (planner == 1 ? r->shortcut_s : 0.0));
        lengths.push_back(v.length.robot);
        grasps.push_back(v.grasps);
      }
      const std::string name = planner == 0 ? planner_name : planner_name + "+shortcut";
      if (planner == 0) medians[{key.first, key.second, planner_name}] = median(times);
      const double rate = static_cast<double>(solved) / static_cast<double>(group.size());
      const double feasible_rate = feasible ? static_cast<double>(solved) / feasible : std::nan("");
      rows.push_back({{"task", key.first}, {"robot", key.second}, {"planner", name},
                      {"runs", group.size()}, {"solved", solved}, {"success_rate", rate},
                      {"feasible_runs", feasible}, {"success_rate_feasible", feasible_rate},
                      {"median_time_s", median(times)}, {"mean_time_s", mean(times)},
                      {"median_path_length_rad", median(lengths)}, {"mean_grasps", mean(grasps)}});
      // A figure over no runs (nothing solved, no feasible instance) is printed as "-".
      auto cell = [](double v, int width, const char* unit = "") {
        std::ostringstream c;
        if (std::isnan(v)) c << "-";
        else c << std::fixed << std::setprecision(2) << v << unit;
        return (std::ostringstream() << std::setw(width) << c.str()).str();
      };
      std::cerr << std::left << std::setw(10) << key.first << std::setw(10) << key.second << std::setw(17) << name
                << std::right << std::setw(6) << group.size() << std::setw(9) << feasible << cell(rate * 100, 9, "%")
                << cell(feasible_rate * 100, 10, "%") << cell(median(times), 10) << cell(mean(times), 9)
                << cell(median(lengths), 12) << cell(mean(grasps), 8) << "\n";
    }
  }
  // Each planner against the first: ratio of median planning times where both solved something.
  nlohmann::json comparisons = nlohmann::json::array();
  for (size_t p = 1; p < planners.size(); ++p) {
    std::cerr << "\nmedian planning time, " << planners[p] << " / " << planners[0] << ":\n";
    for (const auto& [key, group] : groups) {
      const double a = medians.at({key.first, key.second, planners[0]});
      const double b = medians.at({key.first, key.second, planners[p]});
      const double ratio = b / a;  // NaN when either solved nothing
      comparisons.push_back({{"task", key.first}, {"robot", key.second}, {"planner", planners[p]},
                             {"baseline", planners[0]}, {"median_time_ratio", std::isnan(ratio) ? nlohmann::json() : nlohmann::json(ratio)}});
      std::cerr << "  " << std::left << std::setw(10) << key.first << std::setw(10) << key.second << std::right;
      if (std::isnan(ratio)) std::cerr << "-\n";
      else std::cerr << std::fixed << std::setprecision(2) << ratio << std::defaultfloat << "\n";
    }
  }
  std::cerr << "total " << std::lround(total_s) << " s\n";
  if (!o.out.empty()) {
    nlohmann::json all = nlohmann::json::array();
    for (const Run& r : runs) {
      all.push_back({{"planner", r.planner}, {"task", r.task}, {"robot", r.robot}, {"pose", r.pose}, {"seed", r.seed}, {"solved", r.solved},
                     {"valid", r.solved && r.raw.valid}, {"message", r.solved ? r.raw.message : r.message},
                     {"feasible", !instances.at({r.task, r.robot, r.pose})->infeasible},
                     {"planning_time_s", r.time_s}, {"iterations", r.iterations}, {"trees", r.trees},
                     {"nodes", r.nodes}, {"path_length_rad", r.raw.length.robot},
                     {"shortened_path_length_rad", r.shortened.length.robot}, {"grasps", r.raw.grasps}});
      if (!r.regrasp.empty()) all.back()["regrasp"] = r.regrasp;
    }
    nlohmann::json report{{"format", "demoplan-bench"}, {"version", 1}, {"rows", rows}, {"comparisons", comparisons}, {"runs", all}};
    if (o.cell.empty()) report["from"] = o.from, report["handles"] = o.handles;
    else report["cell"] = o.cell, report["demos"] = split_list(o.demos);
    write_json_file_atomic(o.out, report);
  }
  if (!o.ompl_log.empty()) {
    const std::string stem = o.ompl_log.size() > 4 && o.ompl_log.substr(o.ompl_log.size() - 4) == ".log"
                                 ? o.ompl_log.substr(0, o.ompl_log.size() - 4) : o.ompl_log;
    for (const auto& [key, group] : groups)
      // ompl_benchmark_statistics keeps only the experiment name's last word: no spaces.
      write_ompl_log(stem + "_" + key.first + "_" + key.second + ".log", key.first + "-" + key.second, planners, group,
                     group.front()->time_limit, total_s);
  }
  if (o.json) std::cout << nlohmann::json{{"rows", rows}, {"comparisons", comparisons}}.dump() << std::endl;
  return kOk;
}

}  // namespace

Command register_bench_command(CLI::App& app) {
  auto opts = std::make_shared<BenchOptions>();
  CLI::App* sub = app.add_subcommand("bench", "run the benchmark protocol and validate every path");
  CLI::Option* tasks = sub->add_option("--tasks", opts->tasks, "comma-separated tasks")->capture_default_str();
  CLI::Option* robots = sub->add_option("--robots", opts->robots, "comma-separated robots")->capture_default_str();
  CLI::Option* poses = sub->add_option("--poses", opts->poses, "robot base pose ids, e.g. 0-4")->capture_default_str();
  sub->add_option("--seeds", opts->seeds, "seeds, e.g. 1-10")->capture_default_str();
  sub->add_option("--time-limit", opts->time_limit, "seconds per run")->capture_default_str();
  sub->add_option("--waiter-time-limit", opts->waiter_time_limit, "seconds per run of the waiter task (paper: 300)")
      ->capture_default_str();
  CLI::Option* cell = sub->add_option("--cell", opts->cell, "a cell file (docs/cell.md) in place of --tasks, --robots and --poses")
                          ->excludes(tasks)->excludes(robots)->excludes(poses);
  sub->add_option("--demos", opts->demos, "with --cell: comma-separated demonstration files, one task instance each")
      ->needs(cell);
  add_from_option(*sub, opts->from)->excludes(cell);
  add_handles_option(*sub, opts->handles)->excludes(cell);
  sub->add_option("--planner", opts->planner, "planner by name")
      ->check(CLI::IsMember(planner_names()))->capture_default_str();
  sub->add_option("--compare", opts->compare,
                  "planners run alternately on the same runs and compared, e.g. guided,unguided")
      ->check([](const std::string& list) {
        for (const auto& p : split_list(list)) {
          const auto names = planner_names();
          if (std::find(names.begin(), names.end(), p) == names.end()) return "unknown planner '" + p + "'";
        }
        return std::string();
      });
  sub->add_option("--jobs", opts->jobs, "runs in parallel")->check(CLI::PositiveNumber)->capture_default_str();
  sub->add_option("--out", opts->out, "write every run and the table as JSON");
  sub->add_option("--ompl-log", opts->ompl_log, "also write OMPL benchmark logs, one per task and robot");
  sub->add_flag("--json", opts->json, "print {\"rows\": [...]} on stdout");
  add_data_dir_option(*sub, opts->data_dir);
  return {sub, [opts] { return run_bench(*opts); }};
}

}  // namespace demoplan::cli
