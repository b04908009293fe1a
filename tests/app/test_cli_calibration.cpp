// demoplan-cli board, synth-board and calibrate as a user runs them (issue 15): the page at the
// DPI asked for, the JSON keys, and exit 2 with one line naming the file and field on bad input.
#include <gtest/gtest.h>

#include <cmath>

#include <nlohmann/json.hpp>

#include "tests/app/cli_runner.h"

namespace {

namespace fs = std::filesystem;
using Json = nlohmann::json;
using namespace demoplan::testing_support;

class CliCalibration : public ::testing::Test {
protected:
  void SetUp() override { work_ = make_temp_dir("demoplan_test_cli_calibration_"); }
  void TearDown() override {
    std::error_code ec;
    fs::remove_all(work_, ec);
  }
  CliResult run(const std::vector<std::string>& args) const { return run_cli(args, work_); }
  static Json one_object(const CliResult& r) {
    EXPECT_EQ(lines(r.out).size(), 1u) << r.out;
    try {
      return Json::parse(r.out);
    } catch (const Json::exception& e) {
      ADD_FAILURE() << e.what() << "\n" << r.out;
      return Json::object();
    }
  }
  // The one error line of a bad input: exit 2, starting "error: ".
  static std::string error_line(const CliResult& r) {
    EXPECT_EQ(r.code, 2) << r.err;
    EXPECT_TRUE(r.out.empty()) << r.out;
    const auto l = lines(r.err);
    EXPECT_EQ(l.size(), 1u) << r.err;
    return l.empty() ? "" : l.back();
  }
  fs::path work_;
};

// Width and height from a PNG's IHDR chunk.
std::pair<long, long> png_size(const fs::path& p) {
  const std::string bytes = read_text(p);
  if (bytes.size() < 24 || bytes.compare(1, 3, "PNG") != 0) return {-1, -1};
  auto be32 = [&](size_t at) {
    long v = 0;
    for (size_t k = 0; k < 4; ++k) v = v * 256 + static_cast<unsigned char>(bytes[at + k]);
    return v;
  };
  return {be32(16), be32(20)};
}

}  // namespace

TEST_F(CliCalibration, BoardWritesFileAndPageAtTheDpi) {
  const fs::path board = work_ / "board.json", image = work_ / "board.png";
  const CliResult r = run({"board", "--squares", "7x5", "--square-mm", "30", "--marker-mm", "22", "--dictionary",
                           "DICT_5X5_100", "--out", board.string(), "--image", image.string(), "--dpi", "200", "--json"});
  ASSERT_EQ(r.code, 0) << r.err;
  const Json j = one_object(r);
  EXPECT_EQ(j.value("squares_x", 0), 7);
  EXPECT_EQ(j.value("squares_y", 0), 5);
  EXPECT_EQ(j.value("markers", 0), 17);
  EXPECT_EQ(j.value("corners", 0), 24);
  // 210 x 150 mm of board, a 15 mm margin all round and a 28 mm caption, at 200 dpi.
  const double px_per_mm = 200 / 25.4;
  const long w = std::lround(210 * px_per_mm) + 2 * std::lround(15 * px_per_mm);
  const long h = std::lround(150 * px_per_mm) + std::lround(28 * px_per_mm) + 2 * std::lround(15 * px_per_mm);
  EXPECT_EQ(png_size(image), std::make_pair(w, h));
  EXPECT_EQ(j["image_size"], Json::array({w, h}));
  const Json file = Json::parse(read_text(board));
  EXPECT_EQ(file.value("format", ""), "demoplan-charuco-board");
  EXPECT_DOUBLE_EQ(file.value("square_length", 0.0), 0.03);
  EXPECT_DOUBLE_EQ(file.value("marker_length", 0.0), 0.022);
  EXPECT_NE(r.err.find("print at 100 %"), std::string::npos) << r.err;
}

TEST_F(CliCalibration, BoardBadInput) {
  const std::string out = (work_ / "board.json").string();
  std::string e = error_line(run({"board", "--squares", "7x4", "--out", out}));
  EXPECT_NE(e.find("--squares"), std::string::npos) << e;
  EXPECT_NE(e.find("odd"), std::string::npos) << e;
  e = error_line(run({"board", "--squares", "seven", "--out", out}));
  EXPECT_NE(e.find("--squares"), std::string::npos) << e;
  e = error_line(run({"board", "--squares", "7x5", "--square-mm", "20", "--marker-mm", "22", "--out", out}));
  EXPECT_NE(e.find("--marker-mm"), std::string::npos) << e;
  e = error_line(run({"board", "--dictionary", "DICT_FOO", "--out", out}));
  EXPECT_NE(e.find("--dictionary"), std::string::npos) << e;
  // Metres typed as millimetres: a 2.1 m page.
  e = error_line(run({"board", "--square-mm", "300", "--marker-mm", "220", "--out", out, "--image",
                      (work_ / "board.png").string()}));
  EXPECT_NE(e.find("--square-mm"), std::string::npos) << e;
  EXPECT_FALSE(fs::exists(out));
  EXPECT_FALSE(fs::exists(work_ / "board.png"));
}

TEST_F(CliCalibration, SynthBoardThenCalibrateJson) {
  const fs::path dir = work_ / "synth";
  const CliResult s = run({"synth-board", "--out", dir.string(), "--views", "10", "--seed", "3", "--json"});
  ASSERT_EQ(s.code, 0) << s.err;
  const Json sj = one_object(s);
  EXPECT_EQ(sj.value("frames", 0), 10);
  for (const char* f : {"calibration.mp4", "board.json", "camera_truth.json"}) EXPECT_TRUE(fs::exists(dir / f)) << f;

  const fs::path camera = work_ / "camera.json";
  const CliResult r = run({"calibrate", (dir / "calibration.mp4").string(), "--board", (dir / "board.json").string(),
                           "--out", camera.string(), "--json"});
  ASSERT_EQ(r.code, 0) << r.err;
  const Json j = one_object(r);
  for (const char* key : {"rms_px", "views_used", "views_rejected", "fx", "fy", "cx", "cy", "per_view", "image_size"})
    EXPECT_TRUE(j.contains(key)) << key << " in " << r.out;
  EXPECT_EQ(j.value("views_used", 0) + j.value("views_rejected", 0), 10);
  ASSERT_TRUE(j["per_view"].is_array());
  ASSERT_EQ(j["per_view"].size(), 10u);
  for (const auto& v : j["per_view"]) {
    EXPECT_TRUE(v.contains("frame")) << v;
    EXPECT_TRUE(v.contains(v.value("used", false) ? "error_px" : "rejected")) << v;
  }
  EXPECT_LT(std::abs(j.value("fx", 0.0) - 1100) / 1100, 0.01) << r.out;
  const Json file = Json::parse(read_text(camera));
  EXPECT_EQ(file.value("format", ""), "demoplan-camera");
  EXPECT_NE(r.err.find("views looked at 10/10"), std::string::npos) << r.err;  // progress
}

TEST_F(CliCalibration, CalibrateBadInput) {
  const fs::path board = work_ / "board.json";
  // No board file.
  std::string e = error_line(run({"calibrate", (work_ / "none.mp4").string(), "--board", board.string(), "--out",
                                  (work_ / "camera.json").string()}));
  EXPECT_NE(e.find(board.string()), std::string::npos) << e;
  // A board file with an even number of rows: named with its field.
  write_text(board, R"({"format": "demoplan-charuco-board", "version": 1, "squares_x": 7, "squares_y": 6,
                        "square_length": 0.03, "marker_length": 0.022, "dictionary": "DICT_5X5_100"})");
  e = error_line(run({"calibrate", (work_ / "none.mp4").string(), "--board", board.string(), "--out",
                      (work_ / "camera.json").string()}));
  EXPECT_NE(e.find("squares_y"), std::string::npos) << e;
  // A good board, a video that is not one.
  write_text(board, R"({"format": "demoplan-charuco-board", "version": 1, "squares_x": 7, "squares_y": 5,
                        "square_length": 0.03, "marker_length": 0.022, "dictionary": "DICT_5X5_100"})");
  write_text(work_ / "not_a_video.mp4", "hello");
  e = error_line(run({"calibrate", (work_ / "not_a_video.mp4").string(), "--board", board.string(), "--out",
                      (work_ / "camera.json").string()}));
  EXPECT_NE(e.find("not_a_video.mp4"), std::string::npos) << e;
  EXPECT_FALSE(fs::exists(work_ / "camera.json"));
}
