// libFuzzer target: the cell file (core/cell/cell.h, load_cell).
// Any input must load or throw InputError naming the file (tests/fuzz/fuzz_input.h).
#include "core/cell/cell.h"
#include "tests/fuzz/fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  return demoplan::fuzz::run(data, size, "input.cell.json", [](const std::string& file) { demoplan::load_cell(file); });
}
