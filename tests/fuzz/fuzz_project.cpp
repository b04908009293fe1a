// libFuzzer target: the project file (core/project/project.h, load_project).
// Any input must load or throw InputError naming the file (tests/fuzz/fuzz_input.h).
#include "core/project/project.h"
#include "tests/fuzz/fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  return demoplan::fuzz::run(data, size, "input.demoplan", [](const std::string& file) { demoplan::load_project(file); });
}
