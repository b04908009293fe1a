// libFuzzer target: BOP CSV pose estimates (perception/importers/bop_csv.h, load_bop_csv).
// Any input must load or throw InputError naming the file (tests/fuzz/fuzz_input.h).
#include "perception/importers/bop_csv.h"
#include "tests/fuzz/fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  return demoplan::fuzz::run(data, size, "input.csv", [](const std::string& file) { demoplan::perception::load_bop_csv(file); });
}
