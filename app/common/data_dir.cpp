#include "app/common/data_dir.h"

#include <cstdlib>
#include <filesystem>

namespace demoplan::app {

namespace fs = std::filesystem;

namespace {
// The folder holding gtamp/ and sample/: <prefix>/share/demoplan when installed beside the
// running executable, else the source tree's resources/.
fs::path installed_share_dir() {
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  if (ec) return {};
  return exe.parent_path().parent_path() / "share/demoplan";
}
}  // namespace

std::string default_data_dir() {
  if (const char* env = std::getenv("DEMOPLAN_DATA_DIR"); env && *env) return env;
  if (const fs::path share = installed_share_dir(); !share.empty() && fs::exists(share / "gtamp/robots/robots.json"))
    return (share / "gtamp").string();
  if (fs::exists(fs::path(DEMOPLAN_SOURCE_DATA_DIR) / "robots/robots.json")) return DEMOPLAN_SOURCE_DATA_DIR;
  return DEMOPLAN_INSTALL_DATA_DIR;
}

std::string default_sample_project() {
  const fs::path relative = "sample/shelf_1_panda/shelf_1_panda.demoplan";
  if (const fs::path share = installed_share_dir(); !share.empty() && fs::exists(share / relative))
    return (share / relative).string();
  const fs::path source = fs::path(DEMOPLAN_SOURCE_DATA_DIR).parent_path() / relative;
  if (fs::exists(source)) return source.string();
  return {};
}

}  // namespace demoplan::app
