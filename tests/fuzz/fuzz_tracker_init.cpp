// libFuzzer target: the model tracker's start file (perception/tracking/tracker_init.h).
// Any input must load or throw InputError naming the file (tests/fuzz/fuzz_input.h).
#include "perception/tracking/tracker_init.h"
#include "tests/fuzz/fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  return demoplan::fuzz::run(data, size, "input.json",
                             [](const std::string& file) { demoplan::perception::load_tracker_init(file); });
}
