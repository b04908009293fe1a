// demoplan-cli graph: the states and transitions a demonstration gives, and how well each
// transition can be sampled (projection) and sampled collision-free.
#include <chrono>
#include <iostream>
#include <memory>

#include <nlohmann/json.hpp>

#include "app/cli/command.h"
#include "app/cli/task_inputs.h"
#include "core/demo/benchmark_demonstration.h"
#include "core/graph/graph_description.h"
#include "core/graph/pick_feasibility.h"

namespace demoplan::cli {

namespace {

struct GraphOptions {
  TaskInputs inputs;
  int samples = 20;
  unsigned seed = 1;
  bool json = false;
};

int run_graph(const GraphOptions& o) {
  const LoadedTask t = load_task_inputs(o.inputs);
  const ConstraintGraph& graph = *t.instance.problem.graph;
  const FeasibilityReport report = assess_picks(t.scene(), graph, *t.instance.problem.checker, o.samples, o.seed);
  const auto& stats = report.transitions;
  int total_projected = 0, total_free = 0;
  for (const auto& st : stats) total_projected += st.projected, total_free += st.collision_free;
  const double projection_time = report.projection_seconds;
  const int total = o.samples * static_cast<int>(graph.transitions.size());
  const double success_rate = total ? static_cast<double>(total_projected) / total : 0.0;
  const double per_second = projection_time > 0 ? total_projected / projection_time : 0.0;

  nlohmann::json deviation;
  if (o.inputs.cell.empty() && o.inputs.demo.empty() && o.inputs.from == "raw") {
    // How far the poses estimated from the video lie from the cleaned ones.
    const Demonstration clean = demonstration_from_benchmark(t.task, t.scene(), PoseSource::Subgoals);
    const PoseDeviation d = pose_deviation(t.demo(), clean);
    deviation = {{"pairs", d.pairs},
                 {"median_translation_mm", d.median_translation_mm},
                 {"max_translation_mm", d.max_translation_mm},
                 {"median_rotation_deg", d.median_rotation_deg},
                 {"max_rotation_deg", d.max_rotation_deg}};
    std::cerr << "raw poses vs subgoals over " << d.pairs << " (event, object) pairs: median " << d.median_translation_mm
              << " mm / " << d.median_rotation_deg << " deg, max " << d.max_translation_mm << " mm / "
              << d.max_rotation_deg << " deg\n";
  }
  std::cerr << t.scene().name << ", demonstration from " << (o.inputs.demo.empty() ? o.inputs.from : o.inputs.demo) << "\n"
            << describe_graph_text(t.scene(), graph) << "sampling " << o.samples << " per transition:\n";
  for (size_t i = 0; i < graph.transitions.size(); ++i) {
    std::cerr << "  " << graph.transitions[i].name << ": projected " << stats[i].projected << "/" << o.samples
              << ", collision-free " << stats[i].collision_free << "/" << o.samples << "\n";
    for (const auto& [why, n] : stats[i].failures) std::cerr << "      " << n << "x " << why << "\n";
  }
  std::cerr << "projection success " << success_rate * 100 << " %, " << static_cast<long>(per_second)
            << " successful projections/s, collision-free " << total_free << "/" << total << "\n";
  for (const auto& p : report.picks)
    std::cerr << "pick " << p.pick + 1 << " (" << t.scene().objects[p.object].id << "): "
              << (p.feasible() ? "feasible with " + std::to_string(p.handles.size()) + " handle(s)" : p.reason) << "\n";

  bool every_transition_free = true;
  for (const auto& s : stats) every_transition_free &= s.collision_free > 0;
  if (o.json) {
    nlohmann::json d = describe_graph(t.scene(), graph);
    nlohmann::json placements = nlohmann::json::array(), grasps = nlohmann::json::array();
    for (const auto& s : d["states"]) (s["kind"] == "placement" ? placements : grasps).push_back(s);
    nlohmann::json transitions = d["transitions"];
    for (size_t i = 0; i < transitions.size(); ++i) {
      transitions[i]["samples"] = o.samples;
      transitions[i]["success_rate"] = static_cast<double>(stats[i].projected) / o.samples;
      transitions[i]["collision_free_rate"] = static_cast<double>(stats[i].collision_free) / o.samples;
      transitions[i]["failures"] = stats[i].failures;
    }
    nlohmann::json j = describe_inputs(o.inputs);
    j.update(nlohmann::json{{"placement_states", placements},
                                {"grasp_states", grasps},
                                {"transitions", transitions},
                                {"start", d["start"]},
                                {"goal", d["goal"]},
                                {"projection_success_rate", success_rate},
                                {"projections_per_second", per_second},
                                {"collision_free_rate", total ? static_cast<double>(total_free) / total : 0.0},
                                {"picks", describe_picks(t.scene(), report)},
                            {"deviation_from_subgoals", deviation}});
    std::cout << j.dump() << std::endl;
  }
  return every_transition_free ? kOk : kFailed;
}

}  // namespace

Command register_graph_command(CLI::App& app) {
  auto opts = std::make_shared<GraphOptions>();
  CLI::App* sub = app.add_subcommand("graph", "build the states and transitions of a demonstration and sample them");
  add_task_inputs(*sub, opts->inputs);
  sub->add_option("--samples", opts->samples, "samples per transition")->check(CLI::PositiveNumber)->capture_default_str();
  sub->add_option("--seed", opts->seed, "random seed")->capture_default_str();
  sub->add_flag("--json", opts->json, "print one JSON object on stdout");
  return {sub, [opts] { return run_graph(*opts); }};
}

}  // namespace demoplan::cli
