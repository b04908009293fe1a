#include "ui/document/json_preview.h"

#include <algorithm>
#include <nlohmann/json.hpp>

namespace demoplan::ui {

namespace {

// Numbers side by side (a sample's joints), and short lists of words; long texts one per line.
bool scalar_array(const nlohmann::json& j) {
  if (!j.is_array() || std::any_of(j.begin(), j.end(), [](const auto& e) { return e.is_structured(); })) return false;
  return std::all_of(j.begin(), j.end(), [](const auto& e) { return e.is_number(); }) || j.dump().size() <= 120;
}

// Like dump(1), but a sample (an array of numbers) stays on one line: 7 joints side by side
// read better than 7 lines, and a 1 kHz trajectory shows one line per sample.
void write(const nlohmann::json& j, int depth, std::string& out) {
  const std::string pad(static_cast<size_t>(depth) + 1, ' ');
  const std::string close(static_cast<size_t>(depth), ' ');
  if (j.is_object() && !j.empty()) {
    out += "{\n";
    size_t i = 0;
    for (auto it = j.begin(); it != j.end(); ++it, ++i) {
      out += pad + nlohmann::json(it.key()).dump() + ": ";
      write(it.value(), depth + 1, out);
      out += i + 1 < j.size() ? ",\n" : "\n";
    }
    out += close + "}";
  } else if (j.is_array() && !j.empty() && !scalar_array(j)) {
    out += "[\n";
    for (size_t i = 0; i < j.size(); ++i) {
      out += pad;
      write(j[i], depth + 1, out);
      out += i + 1 < j.size() ? ",\n" : "\n";
    }
    out += close + "]";
  } else if (scalar_array(j) && !j.empty()) {
    out += "[";
    for (size_t i = 0; i < j.size(); ++i) out += (i ? ", " : "") + j[i].dump();
    out += "]";
  } else {
    out += j.dump();
  }
}

}  // namespace

std::string readable_json(const std::string& text) {
  const size_t first_newline = text.find('\n');
  if (first_newline != std::string::npos && first_newline + 1 < text.size()) return text;  // already lines
  const nlohmann::json j = nlohmann::json::parse(text, nullptr, /*allow_exceptions=*/false);
  if (j.is_discarded() || !j.is_structured()) return text;
  std::string out;
  write(j, 0, out);
  return out + "\n";
}

}  // namespace demoplan::ui
