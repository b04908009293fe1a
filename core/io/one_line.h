#pragma once
// Text quoted from an input file, made fit for a one-line error message.
#include <string>

namespace demoplan {

// Line breaks, tabs and other control characters escaped (\n, \r, \t, \xNN). Names and values a
// loader quotes in an InputError come from the input and may hold them (an SRDF name "a&#10;b",
// a JSON key "a\nb"; found by fuzz_srdf): the message must stay one line (DESIGN.md).
inline std::string one_line(const std::string& s) {
  static const char* hex = "0123456789abcdef";
  std::string out;
  out.reserve(s.size());
  for (const char c : s) {
    const auto u = static_cast<unsigned char>(c);
    if (c == '\n') out += "\\n";
    else if (c == '\r') out += "\\r";
    else if (c == '\t') out += "\\t";
    else if (u < 0x20 || u == 0x7f) out += std::string("\\x") + hex[u >> 4] + hex[u & 15];
    else out += c;
  }
  return out;
}

}  // namespace demoplan
