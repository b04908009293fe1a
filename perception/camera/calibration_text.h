#pragma once
// What the YAML and the XML calibration readers share: the file read under a size cap, and
// numbers as OpenCV writes them (integers with an optional '+', reals like "900." or
// "-2.6e-01", ".nan" / ".inf" for what is not finite).
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

namespace demoplan::perception {

// A calibration file is a few kB: more than this is refused before it is parsed.
constexpr std::size_t kMaxCalibrationBytes = 4u << 20;

// The file's bytes, at most kMaxCalibrationBytes (also if it grows while read); throws InputError
// naming the file when it is larger or cannot be opened.
std::string read_calibration_text(const std::string& path);

// nullopt unless the whole text is an integer that fits an int.
std::optional<int> parse_opencv_int(std::string_view text);

// nullopt unless the whole text is a number; ".nan" and ".inf" (any case OpenCV writes) give NaN,
// and a number out of double's range gives infinity, so callers reject both as not finite.
std::optional<double> parse_opencv_number(std::string_view text);

}  // namespace demoplan::perception
