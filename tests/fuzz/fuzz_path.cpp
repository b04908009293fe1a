// libFuzzer target: a path file (core/path/path.h, load_path).
// Any input must load or throw InputError naming the file (tests/fuzz/fuzz_input.h).
#include "core/path/path.h"
#include "tests/fuzz/fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  return demoplan::fuzz::run(data, size, "input.json", [](const std::string& file) { demoplan::load_path(file); });
}
