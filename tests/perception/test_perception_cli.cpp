// demoplan-cli synth / extract / evaluate as a user runs them: JSON keys, exit codes, one-line
// errors.
#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

namespace fs = std::filesystem;

namespace {

struct CliRun {
  int code = -1;
  std::string out, err;
};

CliRun run(const std::string& args) {
  const fs::path err_file = fs::temp_directory_path() / ("demoplan_cli_err_" + std::to_string(::getpid()));
  const std::string cmd = std::string(DEMOPLAN_CLI) + " " + args + " 2>" + err_file.string();
  CliRun r;
  FILE* p = popen(cmd.c_str(), "r");
  std::array<char, 4096> buf{};
  while (fgets(buf.data(), buf.size(), p)) r.out += buf.data();
  const int status = pclose(p);
  r.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  std::ifstream in(err_file);
  r.err.assign(std::istreambuf_iterator<char>(in), {});
  fs::remove(err_file);
  return r;
}

}  // namespace

TEST(PerceptionCli, SynthExtractEvaluate) {
  const fs::path dir = fs::temp_directory_path() / ("demoplan_cli_perception_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  const std::string d = dir.string();
  const CliRun s = run("synth --task shelf_0 --robot panda --pose 0 --time-scale 0.5 --seed 3 --out " + d + " --json");
  ASSERT_EQ(s.code, 0) << s.err;
  const auto js = nlohmann::json::parse(s.out);
  EXPECT_EQ(js["events"], 2);
  for (const char* f : {"video.mp4", "camera.json", "scene.json", "truth.json", "truth.tracks.json"}) EXPECT_TRUE(fs::exists(dir / f)) << f;

  const CliRun e = run("extract " + d + "/video.mp4 --camera " + d + "/camera.json --scene " + d + "/scene.json --out " + d +
                    "/demo.json --json");
  ASSERT_EQ(e.code, 0) << e.err;
  const auto je = nlohmann::json::parse(e.out);
  EXPECT_EQ(je["events"].size(), 2u);
  EXPECT_GT(je["extraction_fps"].get<double>(), 0.0);
  EXPECT_TRUE(fs::exists(dir / "demo.tracks.json"));
  // How much of each part's track was measured: a line per part, and in the JSON.
  EXPECT_NE(e.err.find("  YCBV_02: seen in "), std::string::npos) << e.err;
  ASSERT_EQ(je["coverage"].size(), 1u);
  EXPECT_EQ(je["coverage"][0]["object"], "YCBV_02");
  EXPECT_GT(je["coverage"][0]["seen"].get<int>(), je["frames"].get<int>() / 2);
  EXPECT_LE(je["coverage"][0]["seen"].get<int>(), je["frames"].get<int>());

  const CliRun v = run("evaluate " + d + "/demo.json --truth " + d + "/truth.json --json");
  ASSERT_EQ(v.code, 0) << v.err;
  const auto jv = nlohmann::json::parse(v.out);
  for (const char* k : {"event_precision", "event_recall", "median_timing_error_frames", "median_translation_error_mm",
                        "median_rotation_error_deg", "extraction_fps"})
    EXPECT_TRUE(jv.contains(k)) << k;
  EXPECT_DOUBLE_EQ(jv["event_recall"].get<double>(), 1.0);
  EXPECT_DOUBLE_EQ(jv["event_precision"].get<double>(), 1.0);
  // Every frame too, against synth's truth.tracks.json: the markers' estimates within millimetres.
  EXPECT_GT(jv["frame_coverage"].get<double>(), 0.9);
  EXPECT_LT(jv["frame_median_translation_error_mm"].get<double>(), 2.0);
  EXPECT_GE(jv["frame_p95_translation_error_mm"].get<double>(), jv["frame_median_translation_error_mm"].get<double>());

  // Bad input: exit 2 with one line naming the file.
  std::ofstream(dir / "broken.mp4") << "not a video";
  const CliRun b = run("extract " + d + "/broken.mp4 --scene " + d + "/scene.json --out " + d + "/x.json");
  EXPECT_EQ(b.code, 2);
  EXPECT_NE(b.err.find("broken.mp4: frame 0"), std::string::npos) << b.err;
  EXPECT_EQ(std::count(b.err.begin(), b.err.end(), '\n'), 1) << b.err;
  const CliRun t = run("synth --task nosuch_9 --out " + d + "/y");
  EXPECT_EQ(t.code, 2) << t.err;
  fs::remove_all(dir);
}
