// demoplan-cli: the headless entry point to every job of demoplan. The commands that read or
// write video and images run in demoplan-cli-video (video_commands.h), started from here.
#include "app/cli/command.h"
#include "core/scene/bvh_cache.h"
#include "app/cli/video_commands.h"

int main(int argc, char** argv) {
  using namespace demoplan::cli;
  if (argc > 1 && is_video_command(argv[1])) return run_in_video_executable(argv);
  // Meshes parsed and fitted in earlier runs (mesh_store.h, bvh_cache.h): a scene loads
  // without parsing its mesh files or fitting them.
  demoplan::keep_meshes_between_runs();
  CLI::App app{"demoplan: teach a robot cell a task from one video", "demoplan-cli"};
  std::vector<Command> commands{register_check_command(app), register_graph_command(app),
                                register_plan_command(app), register_validate_command(app),
                                register_bench_command(app), register_bench_segments_command(app),
                                register_evaluate_command(app), register_evaluate_tracks_command(app),
                                register_export_command(app), register_figure_command(app),
                                register_part_command(app), register_grasps_command(app),
                                register_demo_command(app), register_place_command(app),
                                register_merge_command(app)};
  // Listed in --help; reached here only after an option before the command's name.
  for (const VideoCommand& c : video_commands()) {
    CLI::App* sub = add_video_subcommand(app, c.name);
    sub->allow_extras()->prefix_command();
    commands.push_back({sub, [argv] { return run_in_video_executable(argv); }});
  }
  return run_command_line(app, commands, argc, argv);
}
