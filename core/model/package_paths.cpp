#include "core/model/package_paths.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/error.h"

namespace demoplan {

namespace fs = std::filesystem;

std::vector<std::string> urdf_package_names(const std::string& urdf_file) {
  std::ifstream in(urdf_file);
  if (!in) throw InputError(urdf_file, "", "cannot be read");
  std::stringstream text;
  text << in.rdbuf();
  const std::string s = text.str();
  static const std::string prefix = "package://";
  std::vector<std::string> names;
  for (size_t at = s.find(prefix); at != std::string::npos; at = s.find(prefix, at + 1)) {
    const size_t begin = at + prefix.size();
    const size_t end = s.find_first_of("/\"'<> \t\r\n", begin);
    if (end == std::string::npos || end == begin || s[end] != '/') continue;
    const std::string name = s.substr(begin, end - begin);
    if (std::find(names.begin(), names.end(), name) == names.end()) names.push_back(name);
  }
  return names;
}

std::vector<std::string> guess_package_paths(const std::string& urdf_file, int levels) {
  std::vector<std::string> paths;
  const fs::path start = fs::absolute(urdf_file).lexically_normal().parent_path();
  for (const std::string& name : urdf_package_names(urdf_file)) {
    fs::path dir = start;
    for (int k = 0; k <= levels && !dir.empty(); ++k, dir = dir.parent_path()) {
      std::error_code ec;
      if (fs::is_directory(dir / name, ec)) {
        const std::string found = dir.string();
        if (std::find(paths.begin(), paths.end(), found) == paths.end()) paths.push_back(found);
        break;
      }
      if (dir == dir.root_path()) break;
    }
  }
  return paths;
}

}  // namespace demoplan
