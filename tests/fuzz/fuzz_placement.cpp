// libFuzzer target: a placement search's result file (core/placement/placement_result.h,
// load_placement_result): what `merge` reads from the shards a cluster wrote.
// Any input must load or throw InputError naming the file (tests/fuzz/fuzz_input.h).
#include "core/placement/placement_result.h"
#include "tests/fuzz/fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  return demoplan::fuzz::run(data, size, "input.json",
                             [](const std::string& file) { demoplan::load_placement_result(file); });
}
