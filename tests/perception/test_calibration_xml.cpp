// Our reader of OpenCV calibration XML (perception/camera/calibration_xml.h), which replaced
// cv::FileStorage for reading: what FileStorage writes reads to the same numbers, and malformed
// files give one line naming the file and the element.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "core/error.h"
#include "perception/camera/calibration_xml.h"
#include "perception/camera/camera_model.h"

namespace fs = std::filesystem;
using namespace demoplan;
using namespace demoplan::perception;

namespace {

const fs::path kSource = DEMOPLAN_SOURCE_DIR;

class CalibrationXmlTest : public ::testing::Test {
protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("demoplan_calibration_xml_" + std::to_string(::getpid()));
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string file(const std::string& name, const std::string& text) {
    const std::string p = (dir_ / name).string();
    std::ofstream(p, std::ios::binary) << text;
    return p;
  }
  fs::path dir_;
};

InputError error_of(const std::string& path) {
  try {
    load_camera(path);
  } catch (const InputError& e) {
    return e;
  }
  return InputError("", "", "");
}

}  // namespace

// The calibration sample's layout, written by cv::FileStorage as XML.
TEST_F(CalibrationXmlTest, ReadsWhatFileStorageWrites) {
  const std::string p = (dir_ / "out_camera_data.xml").string();
  const cv::Matx33d K(535.91573396163199, 0, 342.28315473308373, 0, 535.91573396163199, 235.57082909788173, 0, 0, 1);
  const cv::Mat D = (cv::Mat_<double>(5, 1) << -0.26637260909660682, -0.038588898922304653, 0.0017831947042852964,
                     -0.00028122100441115472, 0.23839153080878486);
  {
    cv::FileStorage fs(p, cv::FileStorage::WRITE);
    fs << "calibration_time" << "Wed Dec  2 08:00:00 2026";
    fs << "nframes" << 12 << "image_width" << 640 << "image_height" << 480 << "flags" << 0;
    fs << "camera_matrix" << cv::Mat(K) << "distortion_coefficients" << D;
    fs << "avg_reprojection_error" << 0.39267218006621659;
    fs << "extrinsic_parameters" << cv::Mat(cv::Mat_<double>(12, 6, 0.125));
  }
  const OpenCvCalibration c = read_calibration_xml(p);
  EXPECT_EQ(c.image_width, 640);
  EXPECT_EQ(c.image_height, 480);
  for (int i = 0; i < 9; ++i) EXPECT_EQ(c.camera_matrix[i], K.val[i]) << i;
  ASSERT_EQ(c.distortion.size(), 5u);
  for (int i = 0; i < 5; ++i) EXPECT_EQ(c.distortion[i], D.at<double>(i)) << i;
  const Camera cam = load_camera((kSource / "tests/fuzz/corpus/camera_xml/good.xml").string());
  EXPECT_EQ(cam.image_size, cv::Size(1280, 720));
  EXPECT_EQ(cam.fx, 900.0);
  EXPECT_EQ(cam.cy, 360.0);
  EXPECT_EQ(cam.distortion, (std::vector<double>{0.1, -0.05, 0, 0, 0}));
}

// 14 bytes on which cv::FileStorage::open of OpenCV 4.6 dereferenced a null pointer.
TEST_F(CalibrationXmlTest, TheFormerCrashInputGivesAOneLineError) {
  const std::string p = (kSource / "tests/data/fuzz-regressions/camera_xml/opencv_xml_parser_segv.xml").string();
  ASSERT_TRUE(fs::is_regular_file(p));
  const std::string what = error_of(p).what();
  EXPECT_EQ(what.rfind(p + ": ", 0), 0u) << what;
  EXPECT_NE(what.find("<opencv_storage>"), std::string::npos) << what;
  EXPECT_EQ(what.find('\n'), std::string::npos) << what;
}

TEST_F(CalibrationXmlTest, MalformedFilesNameTheElement) {
  auto doc = [](const std::string& body) {
    return "<?xml version=\"1.0\"?>\n<opencv_storage>\n<image_width>1280</image_width>\n"
           "<image_height>720</image_height>\n" + body + "</opencv_storage>\n";
  };
  auto matrix = [](const std::string& name, const std::string& rows, const std::string& cols, const std::string& data) {
    return "<" + name + " type_id=\"opencv-matrix\">\n  <rows>" + rows + "</rows>\n  <cols>" + cols +
           "</cols>\n  <dt>d</dt>\n  <data>" + data + "</data></" + name + ">\n";
  };
  const std::string K = matrix("camera_matrix", "3", "3", "900. 0. 640. 0. 900. 360. 0. 0. 1.");
  struct Case {
    const char* what;
    std::string text;
    const char* field;
    const char* message;
  };
  const std::vector<Case> cases{
      {"not XML", "%YAML:1.0\n", "", "XML error"},
      {"an unclosed element", "<?xml version=\"1.0\"?>\n<opencv_storage>\n<K>\n", "line 4", "XML error"},
      {"another root", "<?xml version=\"1.0\"?>\n<robot/>\n", "", "<opencv_storage>"},
      {"no camera matrix", doc(""), "camera_matrix", "missing"},
      {"no rows", doc("<camera_matrix><cols>3</cols><data>1</data></camera_matrix>\n"), "camera_matrix", "opencv-matrix"},
      {"cols not a number", doc(matrix("camera_matrix", "3", "x", "1")), "camera_matrix", "rows and cols"},
      {"cols 2147483647", doc(matrix("K", "1", "2147483647", "1")), "K", "at most 9"},
      {"a 1x3 matrix", doc(matrix("camera_matrix", "1", "3", "1 2 3")), "camera_matrix", "3x3"},
      {"too few numbers", doc(matrix("camera_matrix", "3", "3", "1 2")), "camera_matrix", "= 9 numbers, not 2"},
      {"a word", doc(matrix("camera_matrix", "3", "3", "900. 0. 640. abc 900. 360. 0. 0. 1.")), "camera_matrix",
       "data[3] is not a number: 'abc'"},
      {"NaN", doc(matrix("camera_matrix", "3", "3", ".nan 0. 640. 0. 900. 360. 0. 0. 1.")), "camera_matrix",
       "data[0] is not a finite number"},
      {"zero focal length", doc(matrix("camera_matrix", "3", "3", "0 0 640 0 900 360 0 0 1")), "camera_matrix",
       "focal lengths"},
      {"three distortion coefficients", doc(K + matrix("distortion_coefficients", "1", "3", "0.1 0.2 0.3")),
       "distortion_coefficients", "4, 5, 8, 12 or 14"},
      {"a negative width",
       "<?xml version=\"1.0\"?>\n<opencv_storage>\n<image_width>-5</image_width>\n<image_height>720</image_height>\n" + K +
           "</opencv_storage>\n",
       "image_width", "positive integer"},
  };
  for (size_t i = 0; i < cases.size(); ++i) {
    const Case& m = cases[i];
    SCOPED_TRACE(m.what);
    const std::string p = file("bad_" + std::to_string(i) + ".xml", m.text);
    const InputError e = error_of(p);
    const std::string what = e.what();
    EXPECT_EQ(e.file(), p) << what;
    EXPECT_EQ(e.field(), m.field) << what;
    EXPECT_NE(what.find(m.message), std::string::npos) << what;
    EXPECT_EQ(what.find('\n'), std::string::npos) << what;
  }
}
