#include "app/cli/video_commands.h"

#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <iostream>

namespace demoplan::cli {

const std::vector<VideoCommand>& video_commands() {
  static const std::vector<VideoCommand> commands{
      {"synth", "render a synthetic demonstration video of a benchmark task or a cell, with ground truth"},
      {"extract", "extract grasp/release events and part poses from a demonstration video"},
      {"new", "create a project file from a benchmark task or a cell"},
      {"inspect", "read a project file and the files it names, as the desktop application opens it"},
      {"board", "make a ChArUco calibration board: its file and a page to print"},
      {"markers", "print the parts' markers at true scale"},
      {"calibrate", "camera intrinsics from a video or a folder of images of a ChArUco board"},
      {"synth-board", "render a synthetic calibration video of a ChArUco board, with the true camera"},
  };
  return commands;
}

CLI::App* add_video_subcommand(CLI::App& app, std::string_view name) {
  for (const VideoCommand& c : video_commands())
    if (name == c.name) return app.add_subcommand(c.name, c.description);
  throw std::logic_error("not a video command: " + std::string(name));
}

bool is_video_command(std::string_view name) {
  for (const VideoCommand& c : video_commands())
    if (name == c.name) return true;
  return false;
}

int run_in_video_executable(char** argv) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::path bin = fs::read_symlink("/proc/self/exe", ec).parent_path();
  if (ec) {
    std::cerr << "error: " << argv[1] << " runs in demoplan-cli-video, and this program cannot find its own folder ("
              << ec.message() << ")\n";
    return kFailed;
  }
  // Beside demoplan-cli in the build tree, in <prefix>/lib/demoplan when installed.
  fs::path video = bin / "demoplan-cli-video";
  if (!fs::exists(video)) video = bin.parent_path() / "lib/demoplan/demoplan-cli-video";
  if (!fs::exists(video)) {
    std::cerr << "error: " << argv[1] << " runs in demoplan-cli-video, found neither beside " << bin.string()
              << " nor in ../lib/demoplan\n";
    return kFailed;
  }
  execv(video.c_str(), argv);
  std::cerr << "error: cannot run " << video.string() << ": " << std::strerror(errno) << "\n";
  return kFailed;
}

}  // namespace demoplan::cli
