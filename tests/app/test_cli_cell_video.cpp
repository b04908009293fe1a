// A cell end to end from video (issue 15): synth --cell renders a demonstration of the UR5
// workbench and its calibration video; calibrate, extract (camera pose from the board in the
// video, the calibrated file giving intrinsics only), evaluate against the truth, plan, validate
// and export all succeed, the events are found and the path is valid.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "tests/app/cli_suite.h"

namespace {

namespace fs = std::filesystem;
using Json = nlohmann::json;
using namespace demoplan::testing_support;

const std::string kCell = std::string(DEMOPLAN_DATA_DIR) + "/../cells/ur5_workbench.json";

class CliCellVideo : public CliSuite {
protected:
  // calibrate and extract take no --data-dir.
  static CliResult run_plain(const std::vector<std::string>& args) { return run_cli(args, dir_); }
};

TEST_F(CliCellVideo, SynthesisedDemonstrationOfAnExampleCellIsExtractedAndPlanned) {
  const fs::path d = dir_ / "synth";
  const std::string out = d.string();
  // A shorter video (time scale 0.5) and calibration (12 views) keep the test quick.
  const CliResult s = run({"synth", "--cell", kCell, "--picks", "2", "--seed", "1", "--time-scale", "0.5",
                           "--calibration-views", "12", "--out", out, "--json"});
  ASSERT_EQ(s.code, 0) << s.err;
  const Json sj = Json::parse(s.out);
  EXPECT_EQ(sj["picks"], 2);
  EXPECT_EQ(sj["events"], 4);
  for (const char* f : {"video.mp4", "calibration.mp4", "board.json", "camera_truth.json", "camera.json", "scene.json", "truth.json"})
    EXPECT_TRUE(fs::exists(d / f)) << f;
  const Json scene = Json::parse(std::ifstream(d / "scene.json"));
  ASSERT_TRUE(scene.contains("cell"));
  EXPECT_TRUE(fs::equivalent(d / scene["cell"].get<std::string>(), kCell));

  // The markers a user prints for the cell are the ones the video shows: same parts, ids, sizes
  // and places; the sheet of the scene holds every one of them.
  const CliResult m = run({"markers", "--cell", kCell, "--out", out + "/cell_markers.png", "--write-scene",
                           out + "/printed_scene.json", "--json"});
  ASSERT_EQ(m.code, 0) << m.err;
  const Json printed = Json::parse(std::ifstream(d / "printed_scene.json"));
  EXPECT_TRUE(fs::equivalent(d / printed["cell"].get<std::string>(), kCell));
  ASSERT_EQ(printed["objects"].size(), scene["objects"].size());
  size_t markers = 0;
  for (size_t k = 0; k < scene["objects"].size(); ++k) {
    const Json& a = scene["objects"][k];
    const Json& b = printed["objects"][k];
    EXPECT_EQ(a["id"], b["id"]);
    ASSERT_EQ(a["markers"].size(), b["markers"].size()) << a["id"];
    for (size_t j = 0; j < a["markers"].size(); ++j, ++markers) {
      EXPECT_EQ(a["markers"][j]["id"], b["markers"][j]["id"]);
      EXPECT_NEAR(a["markers"][j]["size"].get<double>(), b["markers"][j]["size"].get<double>(), 1e-6);
      for (int i = 0; i < 3; ++i)
        EXPECT_NEAR(a["markers"][j]["object_T_marker"]["t"][i].get<double>(),
                    b["markers"][j]["object_T_marker"]["t"][i].get<double>(), 1e-6);
    }
  }
  EXPECT_EQ(Json::parse(m.out)["markers"].size(), markers);
  const CliResult sheet = run({"markers", out + "/scene.json", "--out", out + "/sheet.png", "--dpi", "150", "--json"});
  ASSERT_EQ(sheet.code, 0) << sheet.err;
  const Json sj2 = Json::parse(sheet.out);
  EXPECT_EQ(sj2["markers"].size(), markers);
  for (const auto& page : sj2["pages"]) EXPECT_TRUE(fs::exists(page.get<std::string>())) << page;

  const CliResult c = run_plain({"calibrate", out + "/calibration.mp4", "--board", out + "/board.json", "--out",
                           out + "/cam.json", "--json"});
  ASSERT_EQ(c.code, 0) << c.err;
  const Json cam = Json::parse(std::ifstream(d / "cam.json"));
  EXPECT_FALSE(cam.contains("world_T_camera"));  // the pose must come from the board in the video

  const CliResult x = run_plain({"extract", out + "/video.mp4", "--camera", out + "/cam.json", "--scene", out + "/scene.json",
                           "--out", out + "/demo.json", "--json"});
  ASSERT_EQ(x.code, 0) << x.err;
  EXPECT_NE(Json::parse(x.out)["extrinsics"].get<std::string>().find("board"), std::string::npos);

  const CliResult e = run({"evaluate", out + "/demo.json", "--truth", out + "/truth.json", "--json"});
  ASSERT_EQ(e.code, 0) << e.err;
  const Json ej = Json::parse(e.out);
  EXPECT_EQ(ej["event_precision"], 1.0) << e.err;
  EXPECT_EQ(ej["event_recall"], 1.0) << e.err;

  const CliResult p = run({"plan", "--cell", kCell, "--demo", out + "/demo.json", "--seed", "1", "--out", out + "/p.json"});
  ASSERT_EQ(p.code, 0) << p.err;
  const CliResult v = run({"validate", out + "/p.json", "--cell", kCell, "--demo", out + "/demo.json", "--json"});
  ASSERT_EQ(v.code, 0) << v.err;
  EXPECT_TRUE(Json::parse(v.out)["valid"].get<bool>());
  const CliResult x2 = run({"export", out + "/p.json", "--cell", kCell, "--format", "csv", "--out", out + "/x.csv"});
  ASSERT_EQ(x2.code, 0) << x2.err;
  EXPECT_GT(fs::file_size(d / "x.csv"), 0u);
}

TEST_F(CliCellVideo, MarkerSheetsOfNothingOrTooLargeAreRefusedNamingTheField) {
  const fs::path d = dir_ / "badmarkers";
  fs::create_directories(d);
  std::ofstream(d / "empty.json") << R"({"format": "demoplan-marker-scene", "version": 1, "dictionary": "DICT_4X4_100",
    "objects": [{"id": "a", "markers": []}]})";
  std::ofstream(d / "large.json") << R"({"format": "demoplan-marker-scene", "version": 1, "dictionary": "DICT_4X4_100",
    "objects": [{"id": "a", "markers": [{"id": 3, "size": 0.5, "object_T_marker": {"t": [0, 0, 0], "q": [0, 0, 0, 1]}}]}]})";
  const CliResult e = run({"markers", (d / "empty.json").string(), "--out", (d / "e.png").string()});
  EXPECT_EQ(e.code, 2) << e.err;
  EXPECT_NE(e.err.find("empty.json"), std::string::npos) << e.err;
  EXPECT_NE(e.err.find("no part carries a marker"), std::string::npos) << e.err;
  const CliResult l = run({"markers", (d / "large.json").string(), "--out", (d / "l.png").string(), "--paper", "a3"});
  EXPECT_EQ(l.code, 2) << l.err;
  EXPECT_NE(l.err.find("objects[0].markers[0].size"), std::string::npos) << l.err;
  EXPECT_FALSE(fs::exists(d / "l.png"));
}

TEST_F(CliCellVideo, ExtractWithoutCameraPoseOrBoardIsRefusedNamingTheCameraFile) {
  // A camera file with intrinsics only and a scene whose camera file does not exist: nothing
  // says where the camera is.
  const fs::path d = dir_ / "nopose";
  fs::create_directories(d);
  std::ofstream(d / "cam.json") << R"({"format": "demoplan-camera", "version": 1, "image_size": [64, 48],
    "intrinsics": {"fx": 50, "fy": 50, "cx": 32, "cy": 24}, "distortion": []})";
  std::ofstream(d / "scene.json") << R"({"format": "demoplan-marker-scene", "version": 1, "camera": "missing.json",
    "dictionary": "DICT_4X4_100", "objects": [{"id": "a", "markers": [{"id": 0, "size": 0.05,
    "object_T_marker": {"t": [0, 0, 0], "q": [0, 0, 0, 1]}}]}]})";
  const CliResult x = run_plain({"extract", (d / "video.mp4").string(), "--camera", (d / "cam.json").string(), "--scene",
                           (d / "scene.json").string(), "--out", (d / "demo.json").string()});
  EXPECT_EQ(x.code, 2) << x.err;
  EXPECT_NE(x.err.find("cam.json"), std::string::npos) << x.err;
  EXPECT_NE(x.err.find("world_T_camera"), std::string::npos) << x.err;
}

}  // namespace
