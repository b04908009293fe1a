// Our reader of OpenCV calibration YAML (perception/camera/calibration_yaml.h), which replaced
// cv::FileStorage for reading: the files it must read as OpenCV did, and the malformed ones it
// must reject with one line naming the file and the field.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "core/error.h"
#include "perception/camera/calibration_yaml.h"
#include "perception/camera/camera_model.h"

namespace fs = std::filesystem;
using namespace demoplan;
using namespace demoplan::perception;

namespace {

const fs::path kSource = DEMOPLAN_SOURCE_DIR;

class CalibrationYamlTest : public ::testing::Test {
protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("demoplan_calibration_yaml_" + std::to_string(::getpid()));
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

// What the former reader got from a file: cv::FileStorage's nodes, read as it read them. Used
// here only on files known to be safe for OpenCV's parser.
OpenCvCalibration read_with_file_storage(const std::string& path) {
  cv::FileStorage fs(path, cv::FileStorage::READ);
  EXPECT_TRUE(fs.isOpened()) << path;
  auto node = [&](std::initializer_list<const char*> names) -> cv::FileNode {
    for (const char* n : names)
      if (!fs[n].empty()) return fs[n];
    return {};
  };
  auto numbers = [](const cv::FileNode& m) {
    std::vector<double> out;
    for (const cv::FileNode& v : m["data"]) out.push_back(static_cast<double>(v));
    return out;
  };
  OpenCvCalibration c;
  c.image_width = static_cast<int>(fs["image_width"]);
  c.image_height = static_cast<int>(fs["image_height"]);
  const std::vector<double> k = numbers(node({"camera_matrix", "cameraMatrix", "K"}));
  EXPECT_EQ(k.size(), 9u) << path;
  std::copy_n(k.begin(), std::min<size_t>(k.size(), 9), c.camera_matrix.begin());
  if (const cv::FileNode d = node({"distortion_coefficients", "dist_coeffs", "distCoeffs", "D"}); !d.empty())
    c.distortion = numbers(d);
  return c;
}

void expect_same(const OpenCvCalibration& ours, const OpenCvCalibration& opencv) {
  EXPECT_EQ(ours.image_width, opencv.image_width);
  EXPECT_EQ(ours.image_height, opencv.image_height);
  EXPECT_EQ(ours.camera_matrix, opencv.camera_matrix);  // exactly: the same digits parsed
  EXPECT_EQ(ours.distortion, opencv.distortion);
}

// The error load_camera gives, or "" when it loads.
InputError error_of(const std::string& path) {
  try {
    load_camera(path);
  } catch (const InputError& e) {
    return e;
  }
  return InputError("", "", "");
}

}  // namespace

TEST_F(CalibrationYamlTest, TheRepositorysFilesReadAsWithFileStorage) {
  // Named, not globbed: the corpus also holds fuzzer inputs, which OpenCV's parser may hang on.
  const std::vector<fs::path> files{kSource / "tests/fuzz/corpus/camera_yaml/good.yaml",
                                    kSource / "tests/fuzz/corpus/camera_yaml/ros_names.yml",
                                    kSource / "tests/fuzz/corpus/camera_yaml/singular.yaml",
                                    kSource / "tests/data/bad/camera/singular.yaml"};
  for (const fs::path& f : files) {
    SCOPED_TRACE(f.string());
    ASSERT_TRUE(fs::is_regular_file(f));
    expect_same(read_calibration_yaml(f.string()), read_with_file_storage(f.string()));
  }
  // And the numbers themselves, for the sample-like file.
  const OpenCvCalibration good = read_calibration_yaml((kSource / "tests/fuzz/corpus/camera_yaml/good.yaml").string());
  EXPECT_EQ(good.image_width, 1280);
  EXPECT_EQ(good.image_height, 720);
  EXPECT_EQ(good.camera_matrix, (std::array<double, 9>{900, 0, 640, 0, 900, 360, 0, 0, 1}));
  EXPECT_EQ(good.distortion, (std::vector<double>{0.1, -0.05, 0, 0, 0}));
  const Camera ros = load_camera((kSource / "tests/fuzz/corpus/camera_yaml/ros_names.yml").string());
  EXPECT_EQ(ros.image_size, cv::Size(640, 480));
  EXPECT_EQ(ros.fx, 500.0);
  EXPECT_EQ(ros.cy, 240.0);
  EXPECT_EQ(ros.distortion.size(), 4u);
}

// The layout of OpenCV's calibration sample (samples/cpp/calibration.cpp), written by
// cv::FileStorage: strings, other matrices (float, two-channel), data over several lines.
TEST_F(CalibrationYamlTest, ReadsWhatFileStorageWrites) {
  const std::string p = (dir_ / "out_camera_data.yml").string();
  const cv::Matx33d K(535.91573396163199, 0, 342.28315473308373, 0, 535.91573396163199, 235.57082909788173, 0, 0, 1);
  const cv::Mat D = (cv::Mat_<double>(5, 1) << -0.26637260909660682, -0.038588898922304653, 0.0017831947042852964,
                     -0.00028122100441115472, 0.23839153080878486);
  {
    cv::FileStorage fs(p, cv::FileStorage::WRITE);
    fs << "calibration_time" << "Wed Dec  2 06:40:00 2026";
    fs << "nframes" << 12 << "image_width" << 640 << "image_height" << 480;
    fs << "board_width" << 9 << "board_height" << 6 << "square_size" << 0.025 << "flags" << 0;
    fs << "camera_matrix" << cv::Mat(K) << "distortion_coefficients" << D;
    fs << "avg_reprojection_error" << 0.39267218006621659;
    fs << "per_view_reprojection_errors" << cv::Mat(cv::Mat_<float>(12, 1, 0.25f));
    fs << "extrinsic_parameters" << cv::Mat(cv::Mat_<double>(12, 6, 0.125));
    std::vector<cv::Point2f> corners;
    for (int i = 0; i < 54; ++i) corners.emplace_back(10.5f * static_cast<float>(i), 3.25f);
    fs << "image_points" << cv::Mat(corners);
  }
  const OpenCvCalibration c = read_calibration_yaml(p);
  EXPECT_EQ(c.image_width, 640);
  EXPECT_EQ(c.image_height, 480);
  for (int i = 0; i < 9; ++i) EXPECT_EQ(c.camera_matrix[i], K.val[i]) << i;
  ASSERT_EQ(c.distortion.size(), 5u);
  for (int i = 0; i < 5; ++i) EXPECT_EQ(c.distortion[i], D.at<double>(i)) << i;
  expect_same(c, read_with_file_storage(p));
}

// A ROS camera_info file given OpenCV's header: no tags, comments, other keys holding strings and
// matrices, data over several lines.
TEST_F(CalibrationYamlTest, ReadsRosCameraInfoWithTheHeader) {
  const std::string p = file("ost.yaml",
                             "%YAML:1.0\n"
                             "image_width: 640\n"
                             "image_height: 480\n"
                             "camera_name: narrow_stereo  # a comment\n"
                             "camera_matrix:\n"
                             "  rows: 3\n"
                             "  cols: 3\n"
                             "  data: [ 501.2, 0, 319.5,\n"
                             "          0, 502.5, 239.5,\n"
                             "          0, 0, 1 ]\n"
                             "distortion_model: plumb_bob\n"
                             "distortion_coefficients:\n"
                             "  rows: 1\n"
                             "  cols: 5\n"
                             "  data: [-0.1, 0.02, 0.001, -0.002, 0]\n"
                             "rectification_matrix:\n"
                             "  rows: 3\n"
                             "  cols: 3\n"
                             "  data: [1, 0, 0, 0, 1, 0, 0, 0, 1]\n"
                             "projection_matrix:\n"
                             "  rows: 3\n"
                             "  cols: 4\n"
                             "  data: [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0]\n");
  const Camera c = load_camera(p);
  EXPECT_EQ(c.image_size, cv::Size(640, 480));
  EXPECT_EQ(c.fx, 501.2);
  EXPECT_EQ(c.fy, 502.5);
  EXPECT_EQ(c.cx, 319.5);
  EXPECT_EQ(c.distortion, (std::vector<double>{-0.1, 0.02, 0.001, -0.002, 0}));
  expect_same(read_calibration_yaml(p), read_with_file_storage(p));
}

// The 62 bytes on which cv::FileStorage::open of OpenCV 4.6 never returned (fuzz_camera_yaml):
// now a one-line error about its header.
TEST_F(CalibrationYamlTest, TheFormerHangInputGivesAOneLineError) {
  const std::string p = (kSource / "tests/data/fuzz-regressions/camera_yaml/opencv_yaml_parser_hang.yaml").string();
  ASSERT_TRUE(fs::is_regular_file(p));
  const InputError e = error_of(p);
  const std::string what = e.what();
  EXPECT_EQ(what.rfind(p + ": line 1: ", 0), 0u) << what;
  EXPECT_NE(what.find("%YAML:1.0"), std::string::npos) << what;
  EXPECT_EQ(what.find('\n'), std::string::npos) << what;
}

struct Malformed {
  const char* what;
  std::string text;
  const char* field;     // InputError::field()
  const char* message;   // a part of what()
};

TEST_F(CalibrationYamlTest, MalformedFilesNameTheField) {
  const std::string head = "%YAML:1.0\n---\nimage_width: 1280\nimage_height: 720\n";
  const std::string K = "camera_matrix: !!opencv-matrix\n   rows: 3\n   cols: 3\n   dt: d\n"
                        "   data: [ 900., 0., 640., 0., 900., 360., 0., 0., 1. ]\n";
  auto matrix = [](const std::string& name, const std::string& rows, const std::string& cols, const std::string& data) {
    return name + ": !!opencv-matrix\n   rows: " + rows + "\n   cols: " + cols + "\n   dt: d\n   data: " + data + "\n";
  };
  const std::vector<Malformed> cases{
      {"no camera matrix", head, "camera_matrix", "missing"},
      {"a scalar camera matrix", head + "camera_matrix: 5\n", "camera_matrix", "opencv-matrix"},
      {"rows not a number", head + matrix("camera_matrix", "three", "3", "[ 1, 2, 3 ]"), "camera_matrix", "rows and cols"},
      {"no data", head + "camera_matrix: !!opencv-matrix\n   rows: 3\n   cols: 3\n", "camera_matrix", "data is missing"},
      {"a 2x2 camera matrix", head + matrix("camera_matrix", "2", "2", "[ 1, 0, 0, 1 ]"), "camera_matrix", "3x3"},
      {"cols 2147483647", head + matrix("camera_matrix", "1", "2147483647", "[ 1 ]"), "camera_matrix", "at most 9"},
      {"too few numbers", head + matrix("camera_matrix", "3", "3", "[ 1., 2. ]"), "camera_matrix", "= 9 numbers, not 2"},
      {"too many numbers", head + matrix("camera_matrix", "3", "3", "[ 1, 2, 3, 4, 5, 6, 7, 8, 9, 10 ]"), "camera_matrix",
       "more than"},
      {"a word in the data", head + matrix("camera_matrix", "3", "3", "[ 900., 0., 640., abc, 900., 360., 0., 0., 1. ]"),
       "camera_matrix", "data[3] is not a number: 'abc'"},
      {"NaN in the data", head + matrix("camera_matrix", "3", "3", "[ .nan, 0., 640., 0., 900., 360., 0., 0., 1. ]"),
       "camera_matrix", "data[0] is not a finite number"},
      {"1e999 in the data", head + matrix("camera_matrix", "3", "3", "[ 1e999, 0., 640., 0., 900., 360., 0., 0., 1. ]"),
       "camera_matrix", "data[0] is not a finite number"},
      {"data not closed", head + "camera_matrix: !!opencv-matrix\n   rows: 3\n   cols: 3\n   data: [ 1, 2,\n",
       "camera_matrix", "is not closed"},
      {"text after the data", head + matrix("camera_matrix", "3", "3", "[ 1, 0, 0, 0, 1, 0, 0, 0, 1 ] x"),
       "camera_matrix", "text after the closing ']'"},
      {"a zero focal length", head + matrix("camera_matrix", "3", "3", "[ 0, 0, 640, 0, 900, 360, 0, 0, 1 ]"),
       "camera_matrix", "focal lengths"},
      {"K given twice", head + K + K, "camera_matrix", "appears twice"},
      {"three distortion coefficients", head + K + matrix("distortion_coefficients", "1", "3", "[ 0.1, 0.2, 0.3 ]"),
       "distortion_coefficients", "4, 5, 8, 12 or 14"},
      {"a huge distortion matrix", head + K + matrix("D", "1", "100000", "[ 0 ]"), "D", "at most 14"},
      {"no image_height", "%YAML:1.0\n---\nimage_width: 1280\n" + K, "image_height", "missing"},
      {"a negative width", "%YAML:1.0\n---\nimage_width: -1280\nimage_height: 720\n" + K, "image_width",
       "positive integer"},
      {"a fractional height", "%YAML:1.0\n---\nimage_width: 1280\nimage_height: 720.5\n" + K, "image_height",
       "positive integer"},
      {"YAML 2", "%YAML:2.0\n---\n" + K, "line 1", "%YAML:1.0"},
      // As ROS writes camera_info; OpenCV 4.6 refused it too ("Input file is invalid").
      {"no header", "image_width: 1280\nimage_height: 720\n" + K, "line 1", "header '%YAML:1.0'"},
      {"a tab in the indentation", head + "camera_matrix: !!opencv-matrix\n\trows: 3\n", "line 6", "tab"},
      {"a second document", head + K + "---\nimage_width: 5\n", "line 10", "second YAML document"},
      {"a sequence at the top", head + "- 1\n", "line 5", "sequence"},
      {"no colon", head + "camera_matrix\n", "line 5", "key: value"},
      {"an open quote", head + "calibration_time: \"Wed\n" + K, "line 5", "quoted string"},
      {"a matrix line indented less", head + "camera_matrix: !!opencv-matrix\n   rows: 3\n  cols: 3\n", "camera_matrix",
       "indented by 2"},
  };
  for (size_t i = 0; i < cases.size(); ++i) {
    const Malformed& m = cases[i];
    SCOPED_TRACE(m.what);
    const std::string p = file("bad_" + std::to_string(i) + ".yaml", m.text);
    const InputError e = error_of(p);
    const std::string what = e.what();
    EXPECT_EQ(e.file(), p) << what;
    EXPECT_EQ(e.field(), m.field) << what;
    EXPECT_NE(what.find(m.message), std::string::npos) << what;
    EXPECT_EQ(what.find('\n'), std::string::npos) << what;
  }
}

// The reader's caps: a file over 4 MiB is refused before it is parsed.
TEST_F(CalibrationYamlTest, RefusesFilesOverTheCap) {
  const std::string p = file("huge.yaml", "%YAML:1.0\n---\n" + std::string(4u << 20, '#') + "\n");
  const std::string what = error_of(p).what();
  EXPECT_EQ(what, p + ": larger than 4 MiB: not a calibration file");
}
