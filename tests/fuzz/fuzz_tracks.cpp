// libFuzzer target: the pose tracks beside a demonstration (perception/extraction/tracks_file.h,
// load_tracks_file).
// Any input must load or throw InputError naming the file (tests/fuzz/fuzz_input.h).
#include "perception/extraction/tracks_file.h"
#include "tests/fuzz/fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  return demoplan::fuzz::run(data, size, "input.tracks.json", [](const std::string& file) { demoplan::perception::load_tracks_file(file); });
}
