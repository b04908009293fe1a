// demoplan-cli bench-segments: single-state planners compared on the motions a guided solution
// needed. Each benchmark instance is planned once with the guided planner; its path is cut into
// its single-state runs (state_runs.h), and every planner solves every run for every seed, the
// planners taking turns so that a load change hits them alike. Every returned path is checked
// at the validator's step.
#include <algorithm>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <map>
#include <memory>
#include <numeric>
#include <sstream>

#include <nlohmann/json.hpp>

#include "app/cli/command.h"
#include "app/cli/run_statistics.h"
#include "app/cli/list_options.h"
#include "core/demo/benchmark_demonstration.h"
#include "core/demo/benchmark_scene.h"
#include "core/error.h"
#include "core/graph/state_validity.h"
#include "core/io/json_file.h"
#include "core/path/state_runs.h"
#include "core/project/benchmark_instance.h"
#include "core/planning/plan_job.h"
#include "core/planning/single_state/single_state.h"
#include "core/planning/single_state/single_state_check.h"

namespace demoplan::cli {

namespace {

struct SegmentOptions {
  std::string tasks = "shelf_0";
  std::string robots = "panda";
  std::string poses = "0-4";
  std::string seeds = "1-3";
  std::string planners;  // default: ours and OMPL's RRT-Connect when built in
  double time_limit = 10.0;       // s per single-state run
  double plan_time_limit = 60.0;  // s for the guided plan that gives the segments
  bool include_straight = false;
  std::string out, data_dir;
  bool json = false;
};

struct Segment {
  std::string task, robot;
  int pose = 0;
  std::shared_ptr<const PlanningProblem> problem;
  int state = -1;
  std::string state_name;
  Eigen::VectorXd from, to;
};

struct SegmentRun {
  size_t segment = 0;
  std::string planner;
  int seed = 0;
  bool solved = false, valid = false;
  double time_s = 0, length = 0;
  size_t waypoints = 0;
  std::string message;
};


std::vector<std::string> planner_list(const SegmentOptions& o) {
  std::vector<std::string> names = split_list(o.planners);
  if (names.empty()) {
    names = {kOurSingleStatePlanner};
    if (ompl_available()) names.push_back("ompl-rrtconnect");
  }
  const auto known = single_state_planner_names(), ompl = ompl_planner_names();
  for (const auto& n : names) {
    if (std::find(known.begin(), known.end(), n) != known.end()) continue;
    if (std::find(ompl.begin(), ompl.end(), n) != ompl.end())
      throw InputError("command line", "--planners",
                       n + " needs OMPL, and this demoplan-cli was built without it (install libompl-dev and rebuild)");
    std::string list;
    for (const auto& k : known) list += (list.empty() ? "" : ", ") + k;
    throw InputError("command line", "--planners", "unknown planner '" + n + "' (known: " + list + ")");
  }
  return names;
}

int run_bench_segments(const SegmentOptions& o) {
  const std::vector<std::string> planners = planner_list(o);
  const std::vector<int> poses = int_range(o.poses, "--poses"), seeds = int_range(o.seeds, "--seeds");
  std::vector<Segment> segments;
  int straight = 0, unsolved_instances = 0;
  MeshCache meshes;  // every instance of a robot or task loads the same mesh files
  for (const auto& task_name : split_list(o.tasks)) {
    const BenchmarkTask task = load_benchmark_task(o.data_dir, task_name);
    for (const auto& robot : split_list(o.robots)) {
      const std::vector<int> available = benchmark_pose_ids(task, robot);
      for (int pose : poses) {
        if (std::find(available.begin(), available.end(), pose) == available.end()) continue;
        auto scene = std::make_shared<const Scene>(build_benchmark_scene(task, robot, pose, {.mesh_cache = &meshes}));
        auto problem = std::make_shared<const PlanningProblem>(
            make_benchmark_instance(task, scene, PoseSource::Subgoals).problem);
        PlannerSettings settings;
        settings.planner.seed = 1;
        settings.planner.time_limit = o.plan_time_limit;
        const PlanReport plan = run_plan_job(*problem, settings, {}, nullptr, {.assess_on_failure = false});
        if (!plan.valid()) {
          ++unsolved_instances;
          std::cerr << task_name << " " << robot << " pose " << pose << ": no guided plan ("
                    << (plan.solved() ? plan.validation.message : plan.plan.message) << "), skipped\n";
          continue;
        }
        // The planner's own path: its runs are the motions the search had to find (the
        // shortened path's runs are mostly single straight moves already).
        const Path& path = plan.plan.path;
        const StateValidity validity(*scene, *problem->graph, *problem->checker, settings.planner.resolution);
        CollisionData data = problem->checker->make_data();
        int here = 0;
        for (const StateRun& run : state_runs(path)) {
          const Eigen::VectorXd& a = path.waypoints[run.first].q;
          const Eigen::VectorXd& b = path.waypoints[run.last].q;
          // A straight free move is no search for anyone (our RRT-Connect tries it first).
          if (!o.include_straight && validity.segment_free(run.state, a, b, data)) {
            ++straight;
            continue;
          }
          segments.push_back({task_name, robot, pose, problem, run.state, problem->graph->states[run.state].name, a, b});
          ++here;
        }
        std::cerr << task_name << " " << robot << " pose " << pose << ": " << here << " segment(s)\n";
      }
    }
  }
  std::cerr << segments.size() << " segments (" << straight << " straight ones left out), " << planners.size()
            << " planners, " << seeds.size() << " seed(s)\n";

  std::vector<SegmentRun> runs;
  for (size_t s = 0; s < segments.size(); ++s) {
    const Segment& g = segments[s];
    for (int seed : seeds)
      for (const auto& name : planners) {
        SegmentRun& r = runs.emplace_back();
        r.segment = s, r.planner = name, r.seed = seed;
        const SingleStateResult res = solve_single_state(*g.problem, g.state, g.from, g.to, name,
                                                         StopCondition(o.time_limit), static_cast<std::uint64_t>(seed));
        r.solved = res.solved, r.time_s = res.time_s, r.message = res.message;
        if (res.solved) {
          const SingleStateCheck check = check_single_state_path(*g.problem, g.state, res.path, g.from, g.to);
          r.valid = check.valid;
          if (!check.valid) r.message = "INVALID: " + check.message;
          r.length = res.length();
          r.waypoints = res.path.size();
        }
        std::cerr << "  segment " << s << " (" << g.task << " " << g.robot << " pose " << g.pose << ", "
                  << g.state_name << ") seed " << seed << " " << name << ": "
                  << (r.valid ? "ok" : r.solved ? r.message : "not solved (" + r.message + ")") << ", " << std::fixed
                  << std::setprecision(4) << r.time_s << " s\n" << std::defaultfloat;
      }
  }

  // Per planner. Times are over every run (a failure counts the time it took, about the
  // limit), so a planner that fails is not made to look fast.
  std::map<std::string, std::vector<const SegmentRun*>> by_planner;
  for (const auto& r : runs) by_planner[r.planner].push_back(&r);
  auto times_of = [&](const std::string& p) {
    std::vector<double> t;
    for (const SegmentRun* r : by_planner[p]) t.push_back(r->time_s);
    return t;
  };
  const double ours_median = median(times_of(planners.front()));
  nlohmann::json rows = nlohmann::json::array();
  auto cell = [](double v, int width, int precision) {
    std::ostringstream c;
    if (std::isnan(v)) c << "-";
    else c << std::fixed << std::setprecision(precision) << v;
    return (std::ostringstream() << std::setw(width) << c.str()).str();
  };
  std::cerr << "\n" << std::left << std::setw(18) << "planner" << std::right << std::setw(6) << "runs" << std::setw(9)
            << "success" << std::setw(11) << "median s" << std::setw(10) << "mean s" << std::setw(12) << "length rad"
            << "  median s / " << planners.front() << "'s\n";
  for (const auto& name : planners) {
    const auto& group = by_planner[name];
    int ok = 0;
    std::vector<double> lengths;
    for (const SegmentRun* r : group)
      if (r->valid) ++ok, lengths.push_back(r->length);
    const std::vector<double> times = times_of(name);
    const double rate = group.empty() ? std::nan("") : static_cast<double>(ok) / static_cast<double>(group.size());
    const double ratio = median(times) / ours_median;
    rows.push_back({{"planner", name}, {"runs", group.size()}, {"success", ok}, {"success_rate", rate},
                    {"median_time_s", median(times)}, {"mean_time_s", mean(times)},
                    {"median_path_length_rad", median(lengths)}, {"median_time_ratio", ratio}});
    std::cerr << std::left << std::setw(18) << name << std::right << std::setw(6) << group.size()
              << cell(rate * 100, 8, 1) << "%" << cell(median(times), 11, 4) << cell(mean(times), 10, 4)
              << cell(median(lengths), 12, 2) << cell(ratio, 12, 2) << "\n";
  }
  nlohmann::json segs = nlohmann::json::array(), all = nlohmann::json::array();
  for (const auto& g : segments)
    segs.push_back({{"task", g.task}, {"robot", g.robot}, {"pose", g.pose}, {"state", g.state_name},
                    {"distance_rad", (g.to - g.from).norm()}});
  for (const auto& r : runs)
    all.push_back({{"segment", r.segment}, {"planner", r.planner}, {"seed", r.seed}, {"solved", r.solved},
                   {"valid", r.valid}, {"time_s", r.time_s}, {"path_length_rad", r.length},
                   {"waypoints", r.waypoints}, {"message", r.message}});
  const nlohmann::json summary{{"rows", rows}, {"segments", segs}, {"straight_segments_left_out", straight},
                               {"unplanned_instances", unsolved_instances}};
  if (!o.out.empty()) {
    nlohmann::json file = summary;
    file["format"] = "demoplan-bench-segments";
    file["version"] = 1;
    file["runs"] = all;
    write_json_file_atomic(o.out, file);
  }
  if (o.json) std::cout << summary.dump() << std::endl;
  return segments.empty() ? kFailed : kOk;
}

}  // namespace

Command register_bench_segments_command(CLI::App& app) {
  auto opts = std::make_shared<SegmentOptions>();
  CLI::App* sub = app.add_subcommand(
      "bench-segments", "compare single-state planners (ours, OMPL's) on the motions of guided solutions");
  sub->add_option("--tasks", opts->tasks, "comma-separated tasks")->capture_default_str();
  sub->add_option("--robots", opts->robots, "comma-separated robots")->capture_default_str();
  sub->add_option("--poses", opts->poses, "robot base pose ids, e.g. 0-4")->capture_default_str();
  sub->add_option("--seeds", opts->seeds, "seeds of the single-state runs, e.g. 1-3")->capture_default_str();
  std::string names;
  for (const auto& n : single_state_planner_names()) names += (names.empty() ? "" : ", ") + n;
  sub->add_option("--planners", opts->planners,
                  "comma-separated, the first is the reference of the ratio (built in: " + names +
                      "; default: rrtconnect and ompl-rrtconnect when built in)");
  sub->add_option("--time-limit", opts->time_limit, "seconds per single-state run")->capture_default_str();
  sub->add_option("--plan-time-limit", opts->plan_time_limit, "seconds for the guided plan of each instance")
      ->capture_default_str();
  sub->add_flag("--include-straight", opts->include_straight,
                "keep segments whose straight move is free (no search needed)");
  sub->add_option("--out", opts->out, "write every run, the segments and the table as JSON");
  sub->add_flag("--json", opts->json, "print {\"rows\": [...], \"segments\": [...]} on stdout");
  add_data_dir_option(*sub, opts->data_dir);
  return {sub, [opts] { return run_bench_segments(*opts); }};
}

}  // namespace demoplan::cli
