// libFuzzer target: a demoplan-charuco-board JSON file (perception/camera/charuco_board.h,
// load_charuco_board). Any input must load or throw InputError naming the file (tests/fuzz/fuzz_input.h).
#include "perception/camera/charuco_board.h"
#include "tests/fuzz/fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  return demoplan::fuzz::run(data, size, "input.json", [](const std::string& file) {
    const auto board = demoplan::perception::load_charuco_board(file);
    board.make();  // a board that loads must be one OpenCV accepts
  });
}
