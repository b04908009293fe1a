#pragma once
// Numbers as OpenCV writes them into calibration files (YAML and XML alike): integers with an
// optional '+', reals like "900.", "-2.6e-01", and ".nan" / ".inf" for what is not finite.
#include <optional>
#include <string_view>

namespace demoplan::perception {

// nullopt unless the whole text is an integer that fits an int.
std::optional<int> parse_opencv_int(std::string_view text);

// nullopt unless the whole text is a number; ".nan" and ".inf" (any case OpenCV writes) give NaN,
// and a number out of double's range gives infinity, so callers reject both as not finite.
std::optional<double> parse_opencv_number(std::string_view text);

}  // namespace demoplan::perception
