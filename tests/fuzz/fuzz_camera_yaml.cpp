// libFuzzer target: an OpenCV calibration YAML file (perception/camera/camera_model.h, load_camera;
// our reader parses it, perception/camera/calibration_yaml.h; it was cv::FileStorage until that hung).
// Any input must load or throw InputError naming the file (tests/fuzz/fuzz_input.h).
#include "perception/camera/camera_model.h"
#include "tests/fuzz/fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  return demoplan::fuzz::run(data, size, "input.yaml", [](const std::string& file) { demoplan::perception::load_camera(file); });
}
