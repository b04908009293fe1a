// libFuzzer target: a marker scene file (perception/markers/marker_scene.h, load_marker_scene).
// Any input must load or throw InputError naming the file (tests/fuzz/fuzz_input.h).
#include "perception/markers/marker_scene.h"
#include "tests/fuzz/fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  return demoplan::fuzz::run(data, size, "input.json", [](const std::string& file) { demoplan::perception::load_marker_scene(file); });
}
