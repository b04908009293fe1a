// demoplan-cli check: load a benchmark scene, collision-check its start and goal, time checks.
#include <chrono>
#include <iostream>
#include <memory>
#include <optional>
#include <random>

#include <nlohmann/json.hpp>

#include "app/cli/command.h"
#include "app/cli/task_inputs.h"
#include "core/cell/cell_scene.h"
#include "core/demo/benchmark_scene.h"
#include "core/scene/collision_checker.h"

namespace demoplan::cli {

namespace {

struct CheckOptions {
  std::string task = "shelf_1";
  std::string robot = "panda";
  int pose = 0;
  std::string data_dir;
  std::string cell;
  bool json = false;
  double seconds = 1.0;
};

// Full-scene checks per second on uniformly random configurations within the joint limits,
// objects at the start poses, one thread, fixed seed.
double measure_checks_per_second(const CollisionChecker& checker, const SceneState& start,
                                 double seconds) {
  const auto& model = checker.scene().robot.model;
  const Eigen::VectorXd lo = model.lower_limits(), hi = model.upper_limits();
  std::mt19937_64 rng(1);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  auto data = checker.make_data();
  SceneState s = start;
  long checks = 0;
  const auto t0 = std::chrono::steady_clock::now();
  double elapsed = 0.0;
  while (elapsed < seconds) {
    for (int k = 0; k < 64; ++k, ++checks) {
      for (int i = 0; i < model.nq; ++i) s.q[i] = lo[i] + u(rng) * (hi[i] - lo[i]);
      checker.in_collision(s, data);
    }
    elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  }
  return checks / elapsed;
}

int run_check(const CheckOptions& o) {
  const auto t0 = std::chrono::steady_clock::now();
  // A cell has no goal of its own (its demonstration has): its start is checked twice.
  std::optional<BenchmarkTask> task;
  std::optional<Cell> cell;
  std::shared_ptr<const Scene> scene_ptr;
  if (!o.cell.empty()) {
    cell = load_cell(o.cell);
    scene_ptr = load_cell_scene(o.cell, o.data_dir);
  } else {
    task = load_benchmark_task(o.data_dir, o.task);
    scene_ptr = std::make_shared<const Scene>(build_benchmark_scene(*task, o.robot, o.pose));
  }
  const Scene& scene = *scene_ptr;
  const CollisionChecker checker(scene);
  const double load_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();

  auto data = checker.make_data();
  CollisionPair start_hit, goal_hit;
  const SceneState start = cell ? cell_start_state(*cell, scene) : benchmark_start_state(*task, scene);
  const SceneState goal = cell ? start : benchmark_goal_state(*task, scene);
  const bool start_free = !checker.in_collision(start, data, {}, &start_hit);
  const bool goal_free = !checker.in_collision(goal, data, {}, &goal_hit);
  const double cps = measure_checks_per_second(checker, start, o.seconds);

  size_t links = scene.robot.model.links.size();
  std::cerr << scene.name << " (" << (cell ? o.cell : o.data_dir) << ")\n"
            << "  dof                 " << scene.robot.model.nq << "\n"
            << "  links               " << links << "\n"
            << "  collision pairs     " << checker.pair_count() << "\n"
            << "  start               " << (start_free ? "collision-free" : "IN COLLISION: " + start_hit.first + " / " + start_hit.second) << "\n"
            << "  goal                "
            << (cell ? std::string("(a cell's goal is its demonstration's)")
                     : goal_free ? "collision-free" : "IN COLLISION: " + goal_hit.first + " / " + goal_hit.second)
            << "\n"
            << "  checks per second   " << static_cast<long>(cps) << " (random configurations, one thread)\n"
            << "  load time           " << load_s << " s\n";
  if (o.json) {
    nlohmann::json j = cell ? nlohmann::json{{"cell", o.cell}}
                            : nlohmann::json{{"task", o.task}, {"robot", o.robot}, {"pose", o.pose}};
    j.update(nlohmann::json{{"dof", scene.robot.model.nq},
                     {"links", links},
                     {"collision_pairs", checker.pair_count()},
                     {"start_collision_free", start_free},
                     {"goal_collision_free", goal_free},
                     {"checks_per_second", cps},
                     {"load_time_s", load_s}});
    if (!start_free) j["start_collision"] = {start_hit.first, start_hit.second};
    if (!goal_free) j["goal_collision"] = {goal_hit.first, goal_hit.second};
    std::cout << j.dump() << std::endl;
  }
  return start_free && goal_free ? kOk : kFailed;
}

}  // namespace

Command register_check_command(CLI::App& app) {
  auto opts = std::make_shared<CheckOptions>();
  CLI::App* sub = app.add_subcommand("check", "load a benchmark scene or a cell and collision-check its start and goal");
  sub->add_option("--task", opts->task, "task as <task>_<demo>, e.g. shelf_1")->capture_default_str();
  sub->add_option("--robot", opts->robot, "robot name from robots.json: panda, ur5, kmr_iiwa")->capture_default_str();
  auto* pose = sub->add_option("--pose", opts->pose, "robot base pose id of the task")->capture_default_str();
  sub->add_option("--cell", opts->cell, "a cell file (docs/cell.md) in place of --task, --robot and --pose")
      ->excludes("--task")->excludes("--robot")->excludes(pose);
  sub->add_option("--seconds", opts->seconds, "how long to time random collision checks")
      ->check(CLI::PositiveNumber)->capture_default_str();
  sub->add_flag("--json", opts->json, "print one JSON object on stdout");
  add_data_dir_option(*sub, opts->data_dir);
  return {sub, [opts] { return run_check(*opts); }};
}

}  // namespace demoplan::cli
