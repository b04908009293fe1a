#include "perception/camera/opencv_number.h"

#include <charconv>
#include <limits>

namespace demoplan::perception {

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
