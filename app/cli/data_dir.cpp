#include <cstdlib>
#include <filesystem>
#include <unistd.h>

#include "app/cli/command.h"

namespace demoplan::cli {

namespace fs = std::filesystem;

std::string default_data_dir() {
  if (const char* env = std::getenv("DEMOPLAN_DATA_DIR"); env && *env) return env;
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  // Installed: <prefix>/bin/demoplan-cli next to <prefix>/share/demoplan/gtamp.
  if (!ec) {
    const fs::path installed = exe.parent_path().parent_path() / "share/demoplan/gtamp";
    if (fs::exists(installed / "robots/robots.json")) return installed.string();
  }
  if (fs::exists(fs::path(DEMOPLAN_SOURCE_DATA_DIR) / "robots/robots.json")) return DEMOPLAN_SOURCE_DATA_DIR;
  return DEMOPLAN_INSTALL_DATA_DIR;
}

void add_data_dir_option(CLI::App& sub, std::string& data_dir) {
  data_dir = default_data_dir();
  sub.add_option("--data-dir", data_dir, "benchmark-format data folder (default: the bundled one)")
      ->check(CLI::ExistingDirectory);
}

}  // namespace demoplan::cli
