// demoplan-cli demo: a cell's demonstration without a video (core/cell/cell_picks.h): the picks
// of a script, or random ones the robot can do, as the events and poses extraction would find.
#include <iostream>
#include <memory>

#include <nlohmann/json.hpp>

#include "app/cli/command.h"
#include "app/cli/task_inputs.h"
#include "core/cell/cell_picks.h"
#include "core/cell/cell_scene.h"
#include "core/error.h"

namespace demoplan::cli {

namespace {

struct DemoOptions {
  std::string cell;
  std::string script;
  int picks = 3;
  std::uint64_t seed = 1;
  std::string out;
  std::string data_dir;
  bool json = false;
};

int run_demo(const DemoOptions& o) {
  const Cell cell = load_cell(o.cell);
  const std::shared_ptr<const Scene> scene = load_cell_scene(o.cell, o.data_dir);
  const SceneState start = cell_start_state(cell, *scene);
  std::vector<ScriptedPick> picks;
  std::string failure;
  int attempts = 0;
  if (!o.script.empty()) {
    picks = load_pick_script(o.script, *scene);
  } else {
    const RandomPickReport r = random_picks(*scene, start, o.picks, o.seed);
    picks = r.picks, failure = r.failure, attempts = r.attempts;
  }
  const Demonstration demo = demonstration_from_picks(*scene, start, picks, scene->name);
  save_demonstration(o.out, demo);
  std::cerr << scene->name << ": " << picks.size() << " picks";
  if (o.script.empty()) std::cerr << " (seed " << o.seed << ", " << attempts << " poses drawn)";
  std::cerr << ", " << demo.events.size() << " events, written to " << o.out << "\n";
  for (size_t k = 0; k < picks.size(); ++k) {
    const Eigen::Vector3d t = picks[k].to.translation();
    std::cerr << "  pick " << k + 1 << ": " << scene->objects[picks[k].part].id << " to (" << t.x() << ", " << t.y() << ", "
              << t.z() << ")\n";
  }
  if (!failure.empty()) std::cerr << "  fewer picks than asked: " << failure << "\n";
  if (o.json) {
    nlohmann::json list = nlohmann::json::array();
    for (const auto& p : picks) {
      const Eigen::Vector3d t = p.to.translation();
      list.push_back({{"part", scene->objects[p.part].id}, {"to", {t.x(), t.y(), t.z()}}});
    }
    std::cout << nlohmann::json{{"cell", o.cell}, {"out", o.out}, {"picks", list}, {"events", demo.events.size()},
                                {"attempts", attempts}, {"failure", failure}}
                     .dump()
              << std::endl;
  }
  return failure.empty() ? kOk : kFailed;
}

}  // namespace

Command register_demo_command(CLI::App& app) {
  auto o = std::make_shared<DemoOptions>();
  CLI::App* sub = app.add_subcommand("demo", "a cell's demonstration without a video: scripted or random doable picks");
  sub->add_option("--cell", o->cell, "the cell file (docs/cell.md)")->required();
  auto* script = sub->add_option("--script", o->script, "a pick script (demoplan-pick-script) in place of random picks");
  sub->add_option("--picks", o->picks, "how many random picks")->check(CLI::Range(1, 50))->excludes(script)->capture_default_str();
  sub->add_option("--seed", o->seed, "random seed; the same seed gives the same picks")->excludes(script)->capture_default_str();
  sub->add_option("--out", o->out, "the demonstration file to write")->required();
  sub->add_flag("--json", o->json, "print one JSON object on stdout");
  add_data_dir_option(*sub, o->data_dir);
  return {sub, [o] { return run_demo(*o); }};
}

}  // namespace demoplan::cli
