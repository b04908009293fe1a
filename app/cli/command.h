#pragma once
// Shared plumbing of demoplan-cli subcommands. Contract (DESIGN.md): a human summary on stderr,
// with --json exactly one JSON object on stdout; exit 0 ok, 1 job ran but failed, 2 bad input.
#include <CLI/CLI.hpp>
#include <functional>
#include <string>
#include <vector>

namespace demoplan {
struct PlannerSettings;
}

namespace demoplan::cli {

enum ExitCode { kOk = 0, kFailed = 1, kBadInput = 2 };

// Each subcommand registers its options and returns itself with the action to run when selected.
struct Command {
  CLI::App* sub = nullptr;
  std::function<int()> run;
};
Command register_check_command(CLI::App& app);
Command register_graph_command(CLI::App& app);
Command register_plan_command(CLI::App& app);
Command register_validate_command(CLI::App& app);
Command register_bench_command(CLI::App& app);
Command register_bench_segments_command(CLI::App& app);
Command register_synth_command(CLI::App& app);
Command register_extract_command(CLI::App& app);
Command register_evaluate_command(CLI::App& app);
Command register_evaluate_tracks_command(CLI::App& app);
Command register_export_command(CLI::App& app);
Command register_new_command(CLI::App& app);
Command register_inspect_command(CLI::App& app);
Command register_figure_command(CLI::App& app);
Command register_part_command(CLI::App& app);
Command register_grasps_command(CLI::App& app);
Command register_demo_command(CLI::App& app);
Command register_board_command(CLI::App& app);
Command register_markers_command(CLI::App& app);
Command register_calibrate_command(CLI::App& app);
Command register_synth_board_command(CLI::App& app);
Command register_place_command(CLI::App& app);
Command register_merge_command(CLI::App& app);

// Parses the command line and runs the subcommand chosen, with the contract's exit codes and
// one-line errors (demoplan-cli and demoplan-cli-video alike).
int run_command_line(CLI::App& app, const std::vector<Command>& commands, int argc, char** argv);

// --planner, --seed, --time-limit and the planner's tuning options (plan, place).
void add_planner_options(CLI::App& sub, PlannerSettings& settings);

// The benchmark data folder: --data-dir, else $DEMOPLAN_DATA_DIR, else the bundled copy.
std::string default_data_dir();
void add_data_dir_option(CLI::App& sub, std::string& data_dir);

}  // namespace demoplan::cli
