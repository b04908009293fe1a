// demoplan-cli figure and heat maps without Qt 6 (DEMOPLAN_BUILD_UI off): the command exists and says why it
// cannot draw, so scripts get a clear error instead of "unknown subcommand".
#include "app/cli/command.h"
#include "app/cli/placement_summary.h"
#include "core/error.h"

namespace demoplan::cli {

Command register_figure_command(CLI::App& app) {
  CLI::App* sub = app.add_subcommand("figure", "draw the paper's Fig. 4 (needs a build with Qt 6)");
  sub->allow_extras();
  return {sub, [] () -> int { throw InputError("command line", "figure", "this demoplan-cli was built without Qt 6"); }};
}

void write_placement_heat_map(const std::string&, const PlacementResult&) {
  throw InputError("command line", "--heat-map", "this demoplan-cli was built without Qt 6");
}

}  // namespace demoplan::cli
