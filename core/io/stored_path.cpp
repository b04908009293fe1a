#include "core/io/stored_path.h"

#include <filesystem>

namespace demoplan {

namespace fs = std::filesystem;

namespace {
fs::path folder_of(const std::string& file) { return fs::absolute(fs::path(file)).parent_path(); }
}  // namespace

std::string to_stored(const std::string& absolute, const std::string& file) {
  if (absolute.empty()) return "";
  const fs::path p = fs::path(absolute).lexically_normal();
  const fs::path rel = p.lexically_relative(folder_of(file).lexically_normal());
  if (rel.empty()) return p.string();
  return rel.generic_string();
}

std::string from_stored(const std::string& stored, const std::string& file) {
  if (stored.empty()) return "";
  const fs::path p(stored);
  if (p.is_absolute()) return p.lexically_normal().string();
  return (folder_of(file) / p).lexically_normal().string();
}

}  // namespace demoplan
