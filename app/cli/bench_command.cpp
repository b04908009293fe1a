// demoplan-cli bench: the paper's benchmark protocol over tasks, robots, base poses and seeds;
// every found path is checked by the validator. Prints the columns of the paper's Fig. 4.
// --shard I/N runs every N-th run of the list only, for a cluster (packaging/slurm); merge joins them.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iomanip>
#include <iostream>
#include <map>
#include <memory>
#include <mutex>
#include <thread>
#include <unistd.h>

#include <nlohmann/json.hpp>

#include "app/cli/bench_file.h"
#include "app/cli/command.h"
#include "app/cli/list_options.h"
#include "app/cli/task_inputs.h"
#include "core/demo/benchmark_demonstration.h"
#include "core/error.h"
#include "core/io/shards.h"
#include "core/parallel_for.h"
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
  std::string shard = "1/1";
  std::string out, ompl_log, data_dir;
  bool json = false;
};

struct Instance {
  PlanningProblem problem;
  // After the first failed run: can every pick be done from this base pose at all?
  std::once_flag assessed;
  bool infeasible = false;
  std::string infeasible_reason;
};
using InstanceKey = std::tuple<std::string, std::string, int>;  // task, robot, base pose

// What defines the run list and its settings; not --jobs, --out or --shard, which may differ
// between the shards of one benchmark.
nlohmann::json bench_arguments(const BenchOptions& o, const std::vector<int>& poses, const std::vector<int>& seeds,
                               const std::vector<std::string>& planners) {
  nlohmann::json a{{"seeds", seeds}, {"planners", planners}, {"time_limit_s", o.time_limit}};
  if (o.cell.empty())
    a.update({{"tasks", split_list(o.tasks)}, {"robots", split_list(o.robots)}, {"poses", poses},
              {"waiter_time_limit_s", o.waiter_time_limit}, {"from", o.from}, {"handles", o.handles}});
  else a.update({{"cell", o.cell}, {"demos", split_list(o.demos)}});
  return a;
}

// One experiment (a task and robot); per planner two OMPL planners, its own path and shortened.
void write_ompl_log(const std::string& file, const std::string& experiment, const std::vector<std::string>& planners,
                    const std::vector<const BenchRun*>& all_runs, double time_limit, double total_s) {
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
    std::vector<const BenchRun*> runs;
    for (const BenchRun* r : all_runs)
      if (r->planner == name) runs.push_back(r);
    out << (planner == 0 ? name : name + "+shortcut") << "\n0 common properties\n"
        << "9 properties for each run\ntime REAL\nsolved BOOLEAN\ncorrect solution BOOLEAN\nsolution length REAL\n"
           "object translation REAL\nobject rotation REAL\ngrasps INTEGER\ngraph states INTEGER\nseed INTEGER\n"
        << runs.size() << " runs\n";
    for (const BenchRun* r : runs) {
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
  const auto [shard, shards] = parse_shard(o.shard);
  // The whole run list first, in the same order on every machine; the task instances are made
  // only for the runs this shard keeps.
  std::map<InstanceKey, std::function<PlanningProblem()>> make_problem;
  std::vector<BenchRun> runs;
  MeshCache meshes;  // every instance of a robot or task loads the same mesh files
  auto add_runs = [&](const std::string& task, const std::string& robot, int pose, double time_limit) {
    // Planners alternate on each seed, so a slow phase of the machine hits them alike.
    for (int seed : seeds)
      for (const std::string& planner : planners) {
        BenchRun& r = runs.emplace_back();
        r.index = runs.size() - 1;
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
      if (make_problem.count({name, scene->robot.name, 0}))
        throw InputError(demo, "--demos", "two demonstrations are named '" + name + "': rename one");
      make_problem[{name, scene->robot.name, 0}] = [scene, demo] { return cell_task_instance(scene, demo).problem; };
      add_runs(name, scene->robot.name, 0, o.time_limit);
    }
  }
  for (const auto& task_name : o.cell.empty() ? split_list(o.tasks) : std::vector<std::string>{}) {
    auto task = std::make_shared<const BenchmarkTask>(load_benchmark_task(o.data_dir, task_name));
    for (const auto& robot : split_list(o.robots)) {
      const std::vector<int> available = benchmark_pose_ids(*task, robot);
      for (int pose : poses) {
        if (std::find(available.begin(), available.end(), pose) == available.end()) continue;
        make_problem[{task_name, robot, pose}] = [&o, &meshes, task, robot, pose] {
          auto scene = benchmark_scene_with_handles(*task, robot, pose, o.handles, &meshes);
          return make_task_instance(*task, scene, o.from).problem;
        };
        add_runs(task_name, robot, pose, task->task_name == "waiter" ? o.waiter_time_limit : o.time_limit);
      }
    }
  }
  BenchFile bench;
  bench.arguments = bench_arguments(o, poses, seeds, planners);
  bench.run_count = runs.size();
  bench.shard = shard, bench.shards = shards;
  for (int i : shard_indices(static_cast<int>(runs.size()), shard, shards))
    bench.runs.push_back(std::move(runs[static_cast<size_t>(i)]));
  std::map<InstanceKey, std::unique_ptr<Instance>> instances;
  for (const BenchRun& r : bench.runs) {
    std::unique_ptr<Instance>& in = instances[{r.task, r.robot, r.pose}];
    if (in) continue;
    in = std::make_unique<Instance>();
    in->problem = make_problem.at({r.task, r.robot, r.pose})();
  }
  std::cerr << bench.runs.size();
  if (shards > 1) std::cerr << " of " << bench.run_count;
  std::cerr << " runs";
  if (shards > 1) std::cerr << " (shard " << shard << "/" << shards << ")";
  std::cerr << " on " << instances.size() << " task instances, " << o.jobs << " job(s)\n";
  size_t done = 0;
  parallel_for(
      bench.runs.size(), o.jobs,
      [&](size_t i) {
        BenchRun& r = bench.runs[i];
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
      },
      [&](size_t i) {
        const BenchRun& r = bench.runs[i];
        const Instance& in = *instances.at({r.task, r.robot, r.pose});
        ++done;
        std::cerr << "[" << done << "/" << bench.runs.size() << "] " << r.task << " " << r.robot << " pose " << r.pose
                  << " seed " << r.seed << (planners.size() > 1 ? " " + r.planner : "") << ": "
                  << (r.solved ? (r.raw.valid ? "valid" : "INVALID (" + r.raw.message + ")") : "not solved (" + r.message + ")")
                  << ", " << std::fixed << std::setprecision(2) << r.time_s << " s\n" << std::defaultfloat;
        if (!r.solved && in.infeasible) std::cerr << "    infeasible: " << in.infeasible_reason;
      });
  for (BenchRun& r : bench.runs) r.feasible = !instances.at({r.task, r.robot, r.pose})->infeasible;
  const double total_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();

  const BenchTable table = tabulate_bench_runs(bench.runs, planners);
  print_bench_table(table);
  std::cerr << "total " << std::lround(total_s) << " s\n";
  if (!o.out.empty()) save_bench_file(o.out, bench, table);
  if (!o.ompl_log.empty()) {
    std::map<std::pair<std::string, std::string>, std::vector<const BenchRun*>> groups;
    for (const BenchRun& r : bench.runs) groups[{r.task, r.robot}].push_back(&r);
    const std::string stem = o.ompl_log.size() > 4 && o.ompl_log.substr(o.ompl_log.size() - 4) == ".log"
                                 ? o.ompl_log.substr(0, o.ompl_log.size() - 4) : o.ompl_log;
    for (const auto& [key, group] : groups)
      // ompl_benchmark_statistics keeps only the experiment name's last word: no spaces.
      write_ompl_log(stem + "_" + key.first + "_" + key.second + ".log", key.first + "-" + key.second, planners, group,
                     group.front()->time_limit, total_s);
  }
  if (o.json) std::cout << nlohmann::json{{"rows", table.rows}, {"comparisons", table.comparisons}}.dump() << std::endl;
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
  sub->add_option("--shard", opts->shard, "I/N: run only every N-th run of the list, from the I-th; join them with merge")
      ->capture_default_str();
  sub->add_option("--out", opts->out, "write every run and the table as JSON");
  sub->add_option("--ompl-log", opts->ompl_log, "also write OMPL benchmark logs, one per task and robot");
  sub->add_flag("--json", opts->json, "print {\"rows\": [...]} on stdout");
  add_data_dir_option(*sub, opts->data_dir);
  return {sub, [opts] { return run_bench(*opts); }};
}

}  // namespace demoplan::cli
