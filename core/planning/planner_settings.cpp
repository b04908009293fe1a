#include "core/planning/planner_settings.h"

namespace demoplan {

Json planner_settings_to_json(const PlannerSettings& s) {
  const PlannerParams& p = s.planner;
  return Json{{"planner", s.planner_name},
              {"seed", p.seed},
              {"time_limit_s", p.time_limit},
              {"max_iterations", p.max_iterations},
              {"regrasp_after", p.regrasp_after},
              {"eta", p.eta_sample_tree},
              {"step_rad", p.step},
              {"resolution_rad", p.resolution},
              {"shortcut", s.shortcut},
              {"shortcut_time_s", s.shortcutting.time_limit},
              {"feasibility_samples", s.feasibility_samples}};
}

PlannerSettings planner_settings_from_json(const JsonField& j) {
  PlannerSettings s;
  PlannerParams& p = s.planner;
  if (j.has("planner")) s.planner_name = j["planner"].string();
  if (j.has("seed")) {
    if (!j["seed"].value().is_number_unsigned()) j["seed"].fail("must be a non-negative integer");
    p.seed = j["seed"].value().get<std::uint64_t>();
  }
  auto positive = [&](const char* key, double& out) {
    if (!j.has(key)) return;
    out = j[key].number();
    if (out <= 0) j[key].fail("must be > 0");
  };
  positive("time_limit_s", p.time_limit);
  positive("step_rad", p.step);
  positive("resolution_rad", p.resolution);
  if (j.has("max_iterations")) {
    const double v = j["max_iterations"].number();
    if (v < 1) j["max_iterations"].fail("must be >= 1");
    if (v > 1e15) j["max_iterations"].fail("is out of range (at most 1e15)");  // beyond long: UB
    p.max_iterations = static_cast<long>(v);
  }
  if (j.has("regrasp_after")) {
    const double v = j["regrasp_after"].number();
    if (v < 0) j["regrasp_after"].fail("must be >= 0 (0: never)");
    if (v > 1e15) j["regrasp_after"].fail("is out of range (at most 1e15)");
    p.regrasp_after = static_cast<long>(v);
  }
  if (j.has("eta")) {
    p.eta_sample_tree = j["eta"].number();
    if (p.eta_sample_tree < 0 || p.eta_sample_tree > 1) j["eta"].fail("must be within [0, 1]");
  }
  if (j.has("shortcut")) s.shortcut = j["shortcut"].boolean();
  if (j.has("shortcut_time_s")) {
    s.shortcutting.time_limit = j["shortcut_time_s"].number();
    if (s.shortcutting.time_limit < 0) j["shortcut_time_s"].fail("must be >= 0");
  }
  if (j.has("feasibility_samples")) {
    s.feasibility_samples = j["feasibility_samples"].integer();
    if (s.feasibility_samples < 1) j["feasibility_samples"].fail("must be >= 1");
  }
  return s;
}

}  // namespace demoplan
