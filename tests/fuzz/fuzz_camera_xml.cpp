// libFuzzer target: an OpenCV calibration XML file (perception/camera/camera_model.h, load_camera;
// our reader parses it with TinyXML, perception/camera/calibration_xml.h; cv::FileStorage, which
// read it before, crashed on some).
// Any input must load or throw InputError naming the file (tests/fuzz/fuzz_input.h).
#include "perception/camera/camera_model.h"
#include "tests/fuzz/fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  return demoplan::fuzz::run(data, size, "input.xml", [](const std::string& file) { demoplan::perception::load_camera(file); });
}
