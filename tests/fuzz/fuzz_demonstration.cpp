// libFuzzer target: a demonstration file (core/demo/demonstration.h, load_demonstration).
// Any input must load or throw InputError naming the file (tests/fuzz/fuzz_input.h).
#include "core/demo/demonstration.h"
#include "tests/fuzz/fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  return demoplan::fuzz::run(data, size, "input.json", [](const std::string& file) { demoplan::load_demonstration(file); });
}
