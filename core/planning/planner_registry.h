#pragma once
// The planners demoplan offers, by name. Adding a planner: implement Planner in its own file
// and add one line to the table in planner_registry.cpp; `demoplan-cli plan/bench --planner`
// and the project file's "planner" key then know it.
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "core/planning/planner_settings.h"

namespace demoplan {

struct PlannerEntry {
  std::string name;
  std::string description;  // one line, for --help and the GUI
  std::function<std::unique_ptr<Planner>(const PlannerSettings&)> make;
};

const std::vector<PlannerEntry>& registered_planners();
std::vector<std::string> planner_names();
// The planner settings.planner_name names; throws InputError listing the known names.
std::unique_ptr<Planner> make_planner(const PlannerSettings& settings);

}  // namespace demoplan
