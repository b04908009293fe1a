// libFuzzer target: 100DOH hand detections (perception/importers/hand_detections.h, load_hand_detections).
// Any input must load or throw InputError naming the file (tests/fuzz/fuzz_input.h).
#include "perception/importers/hand_detections.h"
#include "tests/fuzz/fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  return demoplan::fuzz::run(data, size, "input.json", [](const std::string& file) { demoplan::perception::load_hand_detections(file); });
}
