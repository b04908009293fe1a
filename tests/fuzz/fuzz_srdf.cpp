// libFuzzer target: an SRDF through our loader (core/model/srdf.h, parse_srdf).
// Any input must load or throw InputError naming the file (tests/fuzz/fuzz_input.h).
#include "core/model/srdf.h"
#include "tests/fuzz/fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static const std::string file = "fuzz.srdf";
  try {
    demoplan::parse_srdf(std::string(reinterpret_cast<const char*>(data), size), file);
  } catch (const demoplan::InputError& e) {
    demoplan::fuzz::check_error(e, file);
  }
  return 0;
}
