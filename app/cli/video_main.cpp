// demoplan-cli-video: the commands of demoplan-cli that read or write video and images
// (video_commands.h). demoplan-cli runs it for them; it answers as demoplan-cli.
#include "app/cli/command.h"
#include "core/scene/bvh_cache.h"

int main(int argc, char** argv) {
  using namespace demoplan::cli;
  // Meshes parsed and fitted in earlier runs (mesh_store.h, bvh_cache.h): a scene loads
  // without parsing its mesh files or fitting them.
  demoplan::keep_meshes_between_runs();
  CLI::App app{"demoplan: teach a robot cell a task from one video", "demoplan-cli"};
  const std::vector<Command> commands{register_synth_command(app),       register_extract_command(app),
                                      register_new_command(app),         register_inspect_command(app),
                                      register_board_command(app),       register_markers_command(app),
                                      register_calibrate_command(app),   register_synth_board_command(app)};
  return run_command_line(app, commands, argc, argv);
}
