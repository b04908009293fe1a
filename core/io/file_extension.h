#pragma once
// A file's kind by the end of its name: ".CSV" and ".csv" alike.
#include <cctype>
#include <filesystem>
#include <string>

namespace demoplan {

// The extension of `path` with its dot ("" for none), lower-cased.
inline std::string lowercase_extension(const std::filesystem::path& path) {
  std::string extension = path.extension().string();
  for (char& c : extension) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return extension;
}

}  // namespace demoplan
