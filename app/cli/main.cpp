// demoplan-cli: the headless entry point to every job of demoplan.
#include <iostream>

#include "app/cli/command.h"
#include "core/error.h"

int main(int argc, char** argv) {
  using namespace demoplan::cli;
  CLI::App app{"demoplan: teach a robot cell a task from one video"};
  app.require_subcommand(1);
  const std::vector<Command> commands{register_check_command(app), register_graph_command(app),
                                      register_plan_command(app), register_validate_command(app),
                                      register_bench_command(app), register_bench_segments_command(app),
                                      register_synth_command(app),
                                      register_extract_command(app), register_evaluate_command(app),
                                      register_evaluate_tracks_command(app),
                                      register_export_command(app), register_new_command(app),
                                      register_inspect_command(app),
                                      register_figure_command(app), register_part_command(app),
                                      register_grasps_command(app), register_demo_command(app),
                                      register_board_command(app), register_markers_command(app),
                                      register_calibrate_command(app),
                                      register_synth_board_command(app),
                                      register_place_command(app), register_merge_command(app)};
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::cerr << "error: " << e.what() << " (see --help)\n";  // one line, as every bad input
    return kBadInput;
  }
  try {
    for (const auto& c : commands)
      if (c.sub->parsed()) return c.run();
  } catch (const demoplan::InputError& e) {
    std::cerr << "error: " << e.what() << "\n";
    return kBadInput;
  } catch (const std::exception& e) {
    std::cerr << "error: " << e.what() << "\n";
    return kFailed;
  }
  return kBadInput;
}
