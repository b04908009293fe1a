#include "perception/camera/calibration_text.h"

#include <charconv>
#include <filesystem>
#include <fstream>
#include <limits>

#include "core/error.h"

namespace demoplan::perception {

std::string read_calibration_text(const std::string& path) {
  std::error_code ec;
  const auto size = std::filesystem::file_size(path, ec);
  if (!ec && size > kMaxCalibrationBytes)
    throw InputError(path, "", "larger than " + std::to_string(kMaxCalibrationBytes >> 20) + " MiB: not a calibration file");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, "", "cannot open the calibration file");
  // At most the cap, also if the file grew since its size was taken.
  std::string text(ec ? kMaxCalibrationBytes : static_cast<size_t>(size), '\0');
  in.read(text.data(), static_cast<std::streamsize>(text.size()));
  text.resize(static_cast<size_t>(in.gcount()));
  return text;
}

std::optional<int> parse_opencv_int(std::string_view s) {
  if (!s.empty() && s[0] == '+') s.remove_prefix(1);
  int x = 0;
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), x);
  if (s.empty() || ec != std::errc() || end != s.data() + s.size()) return std::nullopt;
  return x;
}

std::optional<double> parse_opencv_number(std::string_view s) {
  if (!s.empty() && s[0] == '+') s.remove_prefix(1);
  std::string_view word = s;
  if (!word.empty() && word[0] == '-') word.remove_prefix(1);
  for (const char* w : {".nan", ".NaN", ".NAN", ".Nan", ".inf", ".Inf", ".INF"})
    if (word == w) return std::numeric_limits<double>::quiet_NaN();
  double x = 0;
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), x);
  if (s.empty() || end != s.data() + s.size()) return std::nullopt;
  if (ec == std::errc::result_out_of_range) return std::numeric_limits<double>::infinity();
  if (ec != std::errc()) return std::nullopt;
  return x;
}

}  // namespace demoplan::perception
