// demoplan-cli place: where should the robot stand? Candidate base poses over a region, each
// screened (can every pick be done from there?), planned with a few seeds and timed; ranked by
// success and cycle time. --shard I/N evaluates one slice, for a cluster (packaging/slurm).
#include <chrono>
#include <iostream>
#include <memory>

#include "app/cli/command.h"
#include "app/cli/list_options.h"
#include "app/cli/placement_summary.h"
#include "app/cli/task_inputs.h"
#include "core/error.h"
#include "core/io/shards.h"
#include "core/placement/placement_search.h"
#include "core/project/placement_problem.h"
#include "core/planning/planner_registry.h"

namespace demoplan::cli {

namespace {

struct PlaceOptions {
  TaskInputs inputs;
  PlannerSettings settings;
  std::string region, seeds = "1-3", shard = "1/1", out, heat_map;
  int samples = 50, jobs = 1;
  PlacementSettings placement;
  bool json = false;
  bool published = false;
};

// The planning problem at any base pose, and the reference base the region's default z is from.
struct Search {
  ProblemAtBase problem_at;
  Pose reference = Pose::Identity();
  std::vector<std::pair<int, BasePose>> published;  // the task's own base poses, by id
  std::vector<Footprint> furniture;
};

Search benchmark_search(const TaskInputs& in) {
  const BenchmarkTask task = load_benchmark_task(in.data_dir, in.task);
  const BenchmarkRobot robot = load_benchmark_robot(task.data_dir, in.robot);
  if (!robot.fixed_base)
    throw InputError("command line", "--robot", in.robot + " is mobile: it drives to each pick, there is no base to place");
  auto scene = benchmark_scene_with_handles(task, in.robot, in.pose, in.handles);
  // The demonstration does not depend on where the robot stands: made once.
  auto demo = std::make_shared<const Demonstration>(make_task_instance(task, scene, in.from).demonstration);
  Search s{problem_at_base(scene, std::move(demo), robot), scene->robot.base, {}, furniture_footprints(*scene)};
  for (int id : benchmark_pose_ids(task, in.robot)) {
    const Pose p = benchmark_robot_pose(task, in.robot, id);
    s.published.push_back({id, {p.translation().x(), p.translation().y(), p.translation().z(), std::atan2(p(1, 0), p(0, 0))}});
  }
  return s;
}

Search cell_search(const TaskInputs& in) {
  if (in.demo.empty()) throw InputError(in.cell, "", "a cell needs a demonstration: give --demo");
  auto scene = load_cell_scene(in.cell, in.data_dir);
  if (!scene->robot.fixed_base)
    throw InputError(in.cell, "robot.mobile", "the robot is mobile: it drives to each pick, there is no base to place");
  auto demo = std::make_shared<const Demonstration>(cell_task_instance(scene, in.demo).demonstration);
  return {problem_at_base(scene, std::move(demo), std::nullopt), scene->robot.base, {}, furniture_footprints(*scene)};
}

int run_place(PlaceOptions o) {
  const auto t0 = std::chrono::steady_clock::now();
  const PlacementRegion region = parse_placement_region(o.region);
  const auto [shard, shards] = parse_shard(o.shard);
  if (o.samples < 1) throw InputError("command line", "--samples", "must be at least 1");
  o.placement.seeds.clear();
  for (int seed : int_range(o.seeds, "--seeds")) {
    if (seed < 0) throw InputError("command line", "--seeds", "seeds are not negative");
    o.placement.seeds.push_back(static_cast<std::uint64_t>(seed));
  }
  if (o.placement.seeds.empty()) throw InputError("command line", "--seeds", "no seed given");
  o.placement.planner = o.settings;
  const Search search = o.inputs.cell.empty() ? benchmark_search(o.inputs) : cell_search(o.inputs);

  PlacementResult result;
  const double z = search.reference.translation().z();
  result.arguments = describe_inputs(o.inputs);
  result.arguments.update({{"region", to_string(region)}, {"default_z", z}, {"samples", o.samples},
                           {"seeds", o.placement.seeds}, {"planner", o.settings.planner_name},
                           {"time_limit_s", o.settings.planner.time_limit},
                           {"screen_samples", o.placement.screen_samples},
                           {"plan_rejected", o.placement.plan_rejected}, {"published", o.published}});
  const std::vector<BasePose> candidates = candidate_base_poses(region, o.samples, z);
  const std::vector<int> indices = shard_indices(o.samples, shard, shards);
  result.candidate_count = o.samples;
  result.furniture = search.furniture;
  result.shard = shard, result.shards = shards;
  std::cerr << indices.size() << " of " << o.samples << " candidate base poses over " << to_string(region) << ", seeds "
            << o.seeds << ", " << o.jobs << " job(s)\n";
  result.candidates = run_placement_search(
      search.problem_at, candidates, indices, o.placement, o.jobs,
      [](const PlacementCandidate& c, size_t done, size_t total) {
        std::cerr << "[" << done << "/" << total << "] candidate " << c.index << " (" << c.base.x << ", " << c.base.y
                  << ", yaw " << std::lround(c.base.yaw * 180 / M_PI) << " deg): ";
        // The first words of the reason; the result file has all of it.
        if (!c.feasible)
          std::cerr << "rejected in " << c.screen_time_s << " s: "
                    << (c.reason.size() > 140 ? c.reason.substr(0, 140) + "..." : c.reason);
        else std::cerr << c.success_rate() * 100 << " % valid, cycle " << c.cycle_time_s().value_or(NAN) << " s";
        std::cerr << "\n";
      });
  if (o.published && shard == 1) {
    // The task's own base poses, judged alike: what the search is to beat.
    if (search.published.empty()) throw InputError("command line", "--published", "a cell has no published base poses");
    for (const auto& [id, base] : search.published)
      result.published.push_back(evaluate_candidate(search.problem_at, id, base, o.placement));
  }
  if (result.complete()) rank_candidates(result.candidates);
  result.wall_time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (!o.out.empty()) save_placement_result(o.out, result);
  print_placement_summary(result);
  if (!o.heat_map.empty()) {
    if (!result.complete()) throw InputError("command line", "--heat-map", "a shard draws no heat map: merge first");
    write_placement_heat_map(o.heat_map, result);
  }
  if (o.json) std::cout << placement_summary_json(result, o.out).dump() << std::endl;
  if (!result.complete()) return kOk;
  return result.message().empty() ? kOk : kFailed;
}

}  // namespace

Command register_place_command(CLI::App& app) {
  auto opts = std::make_shared<PlaceOptions>();
  opts->settings.planner.time_limit = 10;
  CLI::App* sub = app.add_subcommand(
      "place", "search the robot's base pose for a task: screen, plan and time candidates over a region, ranked");
  add_task_inputs(*sub, opts->inputs);
  sub->add_option("--region", opts->region,
                  "x0:x1,y0:y1,yaw0:yaw1[,z0:z1]: metres and radians, world frame; without z, the height of the "
                  "reference base (--pose, or the cell's)")
      ->required();
  sub->add_option("--samples", opts->samples, "candidate base poses (a Halton sequence over the region)")
      ->capture_default_str();
  sub->add_option("--seeds", opts->seeds, "planning seeds per candidate, e.g. 1-3")->capture_default_str();
  add_planner_options(*sub, opts->settings);
  sub->remove_option(sub->get_option("--seed"));  // --seeds
  sub->add_option("--screen-samples", opts->placement.screen_samples,
                  "samples per grasp or release in the screen")->check(CLI::PositiveNumber)->capture_default_str();
  sub->add_flag("--plan-rejected", opts->placement.plan_rejected,
                "plan the candidates the screen rejected too (measures the screen)");
  sub->add_flag("--published", opts->published,
                "judge the task's published base poses alike, for comparison (on the heat map: red crosses)");
  sub->add_option("--jobs", opts->jobs, "candidates evaluated at once")->check(CLI::PositiveNumber)->capture_default_str();
  sub->add_option("--shard", opts->shard, "I/N: evaluate only the I-th of N slices; join them with merge")
      ->capture_default_str();
  sub->add_option("--out", opts->out, "write the result (JSON, docs/placement.md)");
  sub->add_option("--heat-map", opts->heat_map, "draw the region as PNG or SVG: cycle time, grey where infeasible");
  sub->add_flag("--json", opts->json, "print one JSON object on stdout");
  return {sub, [opts] { return run_place(*opts); }};
}

}  // namespace demoplan::cli
