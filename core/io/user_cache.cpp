#include "core/io/user_cache.h"

#include <cstdlib>
#include <filesystem>

namespace demoplan {

std::string user_cache_folder(const std::string& name) {
  namespace fs = std::filesystem;
  if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg && *xdg) return (fs::path(xdg) / "demoplan" / name).string();
  if (const char* home = std::getenv("HOME"); home && *home) return (fs::path(home) / ".cache" / "demoplan" / name).string();
  return {};
}

}  // namespace demoplan
