#include "core/planning/planner_registry.h"

#include "core/error.h"
#include "core/planning/guided_planner.h"
#include "core/planning/unguided_planner.h"

namespace demoplan {

const std::vector<PlannerEntry>& registered_planners() {
  static const std::vector<PlannerEntry> planners{
      {"guided", "multi-tree RRT with trees rooted at the demonstration's transitions (Alg. 1-2)",
       [](const PlannerSettings& s) { return std::make_unique<GuidedPlanner>(s.planner); }},
      {"unguided", "M-RRT as HPP searches: start and goal placements only, parts released anywhere on a support",
       [](const PlannerSettings& s) { return std::make_unique<UnguidedPlanner>(s.planner); }},
  };
  return planners;
}

std::vector<std::string> planner_names() {
  std::vector<std::string> names;
  for (const auto& p : registered_planners()) names.push_back(p.name);
  return names;
}

std::unique_ptr<Planner> make_planner(const PlannerSettings& settings) {
  std::string known;
  for (const auto& p : registered_planners()) {
    if (p.name == settings.planner_name) return p.make(settings);
    known += (known.empty() ? "" : ", ") + p.name;
  }
  throw InputError("planner settings", "planner", "unknown planner '" + settings.planner_name + "' (" + known + ")");
}

}  // namespace demoplan
