// demoplan-cli plan: the plan job (core/planning/plan_job.h) on a benchmark task: the chosen
// planner, shortcutting, the independent validator, and after a failure the reason.
#include <chrono>
#include <iostream>
#include <memory>

#include <nlohmann/json.hpp>

#include "app/cli/command.h"
#include "app/cli/task_inputs.h"
#include "core/graph/graph_description.h"
#include "core/planning/plan_job.h"
#include "core/planning/planner_registry.h"
#include "core/scene/bvh_cache.h"

namespace demoplan::cli {

namespace {

struct PlanOptions {
  TaskInputs inputs;
  PlannerSettings settings;
  bool no_shortcut = false;
  std::string out;
  bool json = false;
};

int run_plan(const PlanOptions& o) {
  const auto began = std::chrono::steady_clock::now();
  auto seconds = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - began).count(); };
  const LoadedTask t = load_task_inputs(o.inputs);
  const double load_time_s = seconds();  // the scene, its meshes, the demonstration, the checker
  // Cleaned demonstrations are judged against the benchmark's own start and goal; a plan from
  // the raw video estimates against the start and goal those estimates give.
  const PlanningProblem& problem = t.instance.problem;
  const ConstraintGraph& graph = *problem.graph;
  PlannerSettings settings = o.settings;
  settings.shortcut = !o.no_shortcut;
  const PlanReport s = run_plan_job(problem, settings, {}, nullptr, {.validate_planner_path = false});
  const PlanResult& r = s.plan;
  const std::uint64_t seed = settings.planner.seed;
  nlohmann::json j = describe_inputs(o.inputs);
  j.update(nlohmann::json{{"planner", s.planner},
                   {"seed", seed},            {"solved", r.solved},
                   {"planning_time_s", r.planning_time_s}, {"iterations", r.iterations},
                   {"trees", r.trees},        {"nodes", r.nodes},
                   {"rejected_links", r.rejected_links}, {"load_time_s", load_time_s},
                   {"job_time_s", s.wall_time_s}, {"meshes_fitted", bvh_fits()},
                   {"meshes_read", bvh_reads()}});
  std::cerr << t.scene().name << ", " << s.planner << ", seed " << seed << ": "
            << (r.solved ? "solved" : "not solved: " + r.message) << " in " << r.planning_time_s << " s, "
            << r.iterations << " iterations, " << r.trees << " trees, " << r.nodes << " nodes\n";
  if (!r.regrasp.empty()) {
    j["regrasp"] = r.regrasp;
    std::cerr << "  regrasp the demonstration does not show: " << r.regrasp << "\n";
  }
  if (!r.solved) {
    j["message"] = r.message;
    j["valid"] = false;
    j["validation_message"] = "no path";
    if (!r.unsampled_transitions.empty()) {
      j["unsampled_transitions"] = r.unsampled_transitions;
      std::cerr << "  transitions never sampled collision-free: " << r.unsampled_transitions.size() << " of "
                << graph.transitions.size() << "\n";
    }
    // Say whether the demonstration can be done at all from this base pose, and if not, why.
    const FeasibilityReport& feasibility = *s.feasibility;
    j["picks"] = describe_picks(t.scene(), feasibility);
    j["feasible"] = feasibility.feasible();
    std::cerr << (feasibility.feasible() ? "  every pick has a handle that grasps and releases collision-free\n"
                                         : "  " + feasibility.summary(t.scene()));
    if (o.json) std::cout << j.dump() << std::endl;
    return kFailed;
  }
  Path path = s.path;
  path.robot = t.scene().robot.name;
  if (o.inputs.cell.empty()) {  // a cell's path is judged with the cell and demonstration given again
    path.task = o.inputs.task;
    path.robot_pose = o.inputs.pose;
  }
  if (settings.shortcut) {
    std::cerr << "  shortcut: " << s.shortcut.length_before << " -> " << s.shortcut.length_after << " rad in "
              << s.shortcut.time_s << " s (" << s.shortcut.accepted << " of " << s.shortcut.attempts << " cuts, "
              << s.shortcut.detours_removed << " put-back detours removed)"
              << (s.shortened ? "" : "; dropped: " + s.shortcut_rejection) << "\n";
    j["shortcut"] = {{"length_before", s.shortcut.length_before}, {"length_after", s.shortcut.length_after},
                     {"time_s", s.shortcut.time_s}, {"kept", s.shortened},
                     {"detours_removed", s.shortcut.detours_removed}};
  }
  const ValidationReport& v = s.validation;
  std::cerr << "  validator (" << problem.validation.source << "): " << (v.valid ? "valid" : "INVALID: " + v.message) << "; length robot "
            << v.length.robot << " rad, objects " << v.length.object_translation << " m / " << v.length.object_rotation
            << " rad, " << describe_grasps(v.grasps, v.gripper_closes) << "\n";
  j["validated_against"] = problem.validation.source;
  j["valid"] = v.valid;
  j["validation_message"] = v.message;
  j["path_length"] = {{"robot_rad", v.length.robot}, {"object_m", v.length.object_translation},
                      {"object_rad", v.length.object_rotation}};
  j["grasps"] = v.grasps;
  j["gripper_closes"] = v.gripper_closes;
  j["waypoints"] = path.waypoints.size();
  if (!o.out.empty()) {
    save_path(o.out, path);
    std::cerr << "  saved " << o.out << "\n";
  }
  if (o.json) std::cout << j.dump() << std::endl;
  return v.valid ? kOk : kFailed;
}

}  // namespace

void add_planner_options(CLI::App& sub, PlannerSettings& s) {
  PlannerParams& p = s.planner;
  sub.add_option("--planner", s.planner_name, "planner by name")
      ->check(CLI::IsMember(planner_names()))->capture_default_str();
  sub.add_option("--seed", p.seed, "random seed; the same seed gives the same path")->capture_default_str();
  sub.add_option("--time-limit", p.time_limit, "planning time limit in seconds")->capture_default_str();
  sub.add_option("--max-iterations", p.max_iterations, "planning iteration limit")->capture_default_str();
  sub.add_option("--eta", p.eta_sample_tree, "probability of rooting a tree at a sampled transition")
      ->check(CLI::Range(0.0, 1.0))->capture_default_str();
  sub.add_option("--step", p.step, "tree growth step (joint space, rad)")->check(CLI::PositiveNumber)->capture_default_str();
  sub.add_option("--regrasp-after", p.regrasp_after,
                 "iterations without a path before the guided planner tries regrasps the demonstration does not "
                 "show (0: never)")
      ->check(CLI::NonNegativeNumber)->capture_default_str();
  sub.add_flag_callback("--eager-edges", [&p] { p.lazy_edges = false; },
                        "collision-check every tree edge when it is made, not when a found path uses it");
  sub.add_option("--resolution", p.resolution, "edge collision-check resolution (joint space, rad)")
      ->check(CLI::PositiveNumber)->capture_default_str();
}

Command register_plan_command(CLI::App& app) {
  auto opts = std::make_shared<PlanOptions>();
  CLI::App* sub = app.add_subcommand("plan", "plan a benchmark task or a cell's demonstration (default: the video-guided planner)");
  add_task_inputs(*sub, opts->inputs);
  add_planner_options(*sub, opts->settings);
  sub->add_flag("--no-shortcut", opts->no_shortcut, "keep the planner's path as found");
  sub->add_option("--shortcut-time", opts->settings.shortcutting.time_limit, "seconds spent shortening the path")
      ->capture_default_str();
  sub->add_option("--shortcut-failures", opts->settings.shortcutting.max_failures,
                  "stop shortening after this many attempts in a row that shorten nothing")
      ->capture_default_str();
  sub->add_option("--out", opts->out, "write the path as JSON");
  sub->add_flag("--json", opts->json, "print one JSON object on stdout");
  return {sub, [opts] { return run_plan(*opts); }};
}

}  // namespace demoplan::cli
