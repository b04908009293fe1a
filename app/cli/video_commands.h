#pragma once
// The commands that read or write video and images run in a second executable,
// demoplan-cli-video. OpenCV's video and image modules map about 240 shared libraries, a quarter
// of a second of every start, which plan, check, validate and bench never need; demoplan-cli
// lists these commands in its help and hands them over on the same arguments.
#include <string_view>
#include <vector>

#include "app/cli/command.h"

namespace demoplan::cli {

struct VideoCommand {
  const char* name;
  const char* description;
};
const std::vector<VideoCommand>& video_commands();

// The subcommand `name` (one of video_commands()) with its description.
CLI::App* add_video_subcommand(CLI::App& app, std::string_view name);

bool is_video_command(std::string_view name);

// Replaces this process with demoplan-cli-video (beside this executable) run on `argv`; returns
// only when it cannot, with a message on stderr and kFailed.
int run_in_video_executable(char** argv);

}  // namespace demoplan::cli
