#pragma once
// How to plan, as one value shared by the CLI's options, the project file and the GUI's
// planner panel: which planner, its parameters (seed and time limit included), shortcutting,
// and how hard to look for the reason after a failure.
//
// JSON (the project file's "planner" object; every key optional):
//   {"planner": "guided", "seed": 1, "time_limit_s": 60, "max_iterations": 10000000,
//    "eta": 0.1, "step_rad": 0.3, "resolution_rad": 0.005, "shortcut": true,
//    "shortcut_time_s": 1, "feasibility_samples": 100}
#include <string>

#include "core/io/json_file.h"
#include "core/planning/planner.h"
#include "core/planning/shortcut.h"

namespace demoplan {

struct PlannerSettings {
  std::string planner_name = "guided";  // planner_registry.h
  PlannerParams planner;
  bool shortcut = true;
  ShortcutParams shortcutting;  // its seed is the planner's (PlanJob sets it)
  // Samples per transition when a failed plan asks whether each pick can be done at all.
  int feasibility_samples = 100;
};

Json planner_settings_to_json(const PlannerSettings& settings);
// Throws InputError naming the file and the field.
PlannerSettings planner_settings_from_json(const JsonField& json);

}  // namespace demoplan
