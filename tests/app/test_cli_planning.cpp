// plan, validate and bench as a user runs them: the JSON keys the issue lists, the path file
// that validate reads back, the validator's verdict on a path broken by hand, the reason a
// demonstration cannot be done from a base pose, and the benchmark table with OMPL logs.
#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include <nlohmann/json.hpp>

#include "tests/app/cli_suite.h"
#include "tests/support/data_2024.h"

namespace {

namespace fs = std::filesystem;
using Json = nlohmann::json;
using namespace demoplan::testing_support;

// The first line `command` prints on stdout (empty when none or when it fails).
std::string run_shell(const std::string& command) {
  std::string out;
  if (FILE* p = popen((command + " 2>/dev/null").c_str(), "r")) {
    char buf[4096];
    while (fgets(buf, sizeof buf, p)) out += buf;
    pclose(p);
  }
  const auto nl = out.find('\n');
  return nl == std::string::npos ? out : out.substr(0, nl);
}

class CliPlanning : public CliSuite {
protected:
  static Json one_object(const CliResult& r) {
    EXPECT_EQ(lines(r.out).size(), 1u) << r.out;
    return Json::parse(r.out);
  }
  // shelf_0 (one object) from Panda pose 1, planned once and shared.
  static const fs::path& planned() {
    static const fs::path file = [] {
      const fs::path f = dir_ / "shelf_0.json";
      const CliResult r = run({"plan", "--task", "shelf_0", "--robot", "panda", "--pose", "1", "--seed", "1",
                               "--time-limit", "60", "--out", f.string(), "--json"});
      EXPECT_EQ(r.code, 0) << r.err;
      return f;
    }();
    return file;
  }
};

TEST_F(CliPlanning, PlanPrintsTheIssuesKeysAndAValidPath) {
  const CliResult r = run({"plan", "--task", "shelf_0", "--robot", "panda", "--pose", "1", "--seed", "2",
                           "--time-limit", "60", "--json"});
  ASSERT_EQ(r.code, 0) << r.err;
  const Json j = one_object(r);
  for (const char* key : {"solved", "planning_time_s", "iterations", "trees", "nodes", "valid", "validation_message",
                          "path_length", "grasps"})
    EXPECT_TRUE(j.contains(key)) << key << " in " << r.out;
  EXPECT_TRUE(j["solved"].get<bool>());
  EXPECT_TRUE(j["valid"].get<bool>()) << j["validation_message"];
  EXPECT_EQ(j["grasps"].get<int>(), 1);
  for (const char* key : {"robot_rad", "object_m", "object_rad"}) EXPECT_GT(j["path_length"][key].get<double>(), 0.0);
  // The object travels at least from its start to its goal (the straight-line distance).
  EXPECT_GT(j["path_length"]["object_m"].get<double>(), 0.2);
}

// Without markers (issue 16): shelf_1's video, its two parts followed by the model tracker from
// their start poses, gives a demonstration the planner turns into a valid path (its measured
// rest poses put onto their supports first).
TEST_F(CliPlanning, AMarkerFreeDemonstrationIsPlannedValid) {
  const std::string d = (dir_ / "no_markers").string();
  const CliResult s = run({"synth", "--task", "shelf_1", "--no-markers", "--detections", "--out", d, "--json"});
  ASSERT_EQ(s.code, 0) << s.err;
  // Bad starts first: a missing start file, and one that puts a part beside the picture.
  const CliResult missing = run({"extract", d + "/video.mp4", "--scene", d + "/scene.json", "--tracker", "model",
                                 "--init", d + "/nothing.json", "--out", d + "/bad.json"});
  EXPECT_EQ(missing.code, 2);
  EXPECT_NE(missing.err.find("nothing.json"), std::string::npos) << missing.err;
  Json init = Json::parse(std::ifstream(d + "/init.json"));
  init["parts"][1]["world_T_object"]["t"][1] = 25.0;  // 25 m to the side
  std::ofstream(d + "/aside.json") << init.dump();
  const CliResult aside = run({"extract", d + "/video.mp4", "--scene", d + "/scene.json", "--tracker", "model",
                               "--init", d + "/aside.json", "--out", d + "/bad.json"});
  EXPECT_EQ(aside.code, 2);
  EXPECT_NE(aside.err.find("aside.json"), std::string::npos) << aside.err;
  EXPECT_NE(aside.err.find("parts[1].world_T_object"), std::string::npos) << aside.err;
  EXPECT_NE(aside.err.find(init["parts"][1]["id"].get<std::string>()), std::string::npos) << aside.err;
  EXPECT_FALSE(fs::exists(d + "/bad.json"));

  const CliResult x = run({"extract", d + "/video.mp4", "--scene", d + "/scene.json", "--tracker", "model", "--out",
                           d + "/demo.json", "--json"});
  ASSERT_EQ(x.code, 0) << x.err;
  const CliResult e = run({"evaluate", d + "/demo.json", "--truth", d + "/truth.json", "--json"});
  ASSERT_EQ(e.code, 0) << e.err;
  EXPECT_EQ(one_object(e)["event_recall"].get<double>(), 1.0) << e.out;
  // Rests put onto the shelf along the camera's line of sight: 3.0 mm at worst (18.6 mm without).
  EXPECT_LT(one_object(e)["max_translation_error_mm"].get<double>(), 10.0) << e.out;
  const CliResult r = run({"plan", "--task", "shelf_1", "--robot", "panda", "--pose", "0", "--demo", d + "/demo.json",
                           "--seed", "1", "--json"});
  ASSERT_EQ(r.code, 0) << r.err;
  const Json j = one_object(r);
  EXPECT_TRUE(j["solved"].get<bool>());
  EXPECT_TRUE(j["valid"].get<bool>()) << j["validation_message"];
  EXPECT_EQ(j["grasps"].get<int>(), 2);

  // Started from a pose estimator's output instead (synth's simulated BOP results, a few
  // millimetres off): the same events, the rests within a centimetre.
  const CliResult b = run({"extract", d + "/video.mp4", "--scene", d + "/scene.json", "--tracker", "model", "--init",
                           d + "/bop.csv", "--out", d + "/demo_bop.json"});
  ASSERT_EQ(b.code, 0) << b.err;
  EXPECT_NE(b.err.find("start from " + d + "/bop.csv: frame 0"), std::string::npos) << b.err;
  const CliResult eb = run({"evaluate", d + "/demo_bop.json", "--truth", d + "/truth.json", "--json"});
  ASSERT_EQ(eb.code, 0) << eb.err;
  EXPECT_EQ(one_object(eb)["event_recall"].get<double>(), 1.0) << eb.out;
  EXPECT_EQ(one_object(eb)["event_precision"].get<double>(), 1.0) << eb.out;
  EXPECT_LT(one_object(eb)["max_translation_error_mm"].get<double>(), 10.0) << eb.out;
  // Estimates of only one of the two parts: no start, the file and the part named.
  std::ifstream all(d + "/bop.csv");
  std::ofstream one(d + "/bop_one.csv");
  for (std::string line; std::getline(all, line);)
    if (line.find(",5,") == std::string::npos) one << line << "\n";
  one.close();
  const CliResult partial = run({"extract", d + "/video.mp4", "--scene", d + "/scene.json", "--tracker", "model",
                                 "--init", d + "/bop_one.csv", "--out", d + "/bad.json"});
  EXPECT_EQ(partial.code, 2);
  EXPECT_NE(partial.err.find("bop_one.csv"), std::string::npos) << partial.err;
  EXPECT_NE(partial.err.find("'YCBV_05'"), std::string::npos) << partial.err;
  EXPECT_FALSE(fs::exists(d + "/bad.json"));
}

TEST_F(CliPlanning, ASecondRunReadsTheFittedMeshesAndPlansTheSame) {
  // Fitted meshes are kept in the user's cache folder (here a fresh one): the first run fits and
  // stores them, the second reads them instead, and plans exactly as the first (the shortcut,
  // bounded by time, left out).
  const std::string env = "XDG_CACHE_HOME=" + shell_quote((dir_ / "cache").string()) + " ";
  const std::vector<std::string> args = {"plan", "--task", "shelf_0", "--robot", "panda", "--pose", "1", "--seed", "3",
                                         "--time-limit", "60", "--no-shortcut", "--json", "--data-dir", DEMOPLAN_DATA_DIR};
  const CliResult first = run_cli(args, dir_, env);
  ASSERT_EQ(first.code, 0) << first.err;
  const CliResult second = run_cli(args, dir_, env);
  ASSERT_EQ(second.code, 0) << second.err;
  const Json a = one_object(first), b = one_object(second);
  EXPECT_GT(a["meshes_fitted"].get<int>(), 5) << first.out;  // the Panda's links, the shelf, the part
  EXPECT_EQ(a["meshes_read"].get<int>(), 0);
  EXPECT_EQ(b["meshes_fitted"].get<int>(), 0) << second.out;
  EXPECT_EQ(b["meshes_read"], a["meshes_fitted"]);
  EXPECT_TRUE(fs::exists(dir_ / "cache" / "demoplan" / "meshes"));
  ASSERT_TRUE(a["solved"].get<bool>());
  EXPECT_TRUE(b["valid"].get<bool>()) << b["validation_message"];
  for (const char* key : {"iterations", "nodes", "trees", "path_length", "grasps"}) EXPECT_EQ(a[key], b[key]) << key;
}

TEST_F(CliPlanning, ValidateReadsThePlannedPathBack) {
  const CliResult r = run({"validate", planned().string(), "--task", "shelf_0", "--robot", "panda", "--pose", "1",
                           "--json"});
  ASSERT_EQ(r.code, 0) << r.err;
  const Json j = one_object(r);
  for (const char* key : {"valid", "message", "path_length", "grasps"}) EXPECT_TRUE(j.contains(key)) << key;
  EXPECT_TRUE(j["valid"].get<bool>()) << j["message"];
}

TEST_F(CliPlanning, ValidateRejectsAPathMovedOffItsStart) {
  Json path = Json::parse(read_text(planned()));
  ASSERT_TRUE(path.contains("waypoints")) << "path file layout changed";
  auto& q = path["waypoints"][0]["q"];
  q[0] = q[0].get<double>() + 0.3;  // the robot no longer starts at its initial configuration
  const fs::path broken = dir_ / "broken.json";
  write_text(broken, path.dump());
  const CliResult r = run({"validate", broken.string(), "--task", "shelf_0", "--robot", "panda", "--pose", "1",
                           "--json"});
  EXPECT_EQ(r.code, 1) << r.err;
  const Json j = one_object(r);
  EXPECT_FALSE(j["valid"].get<bool>());
  EXPECT_NE(j["message"].get<std::string>().find("start"), std::string::npos) << j["message"];
}

TEST_F(CliPlanning, PlanSaysWhichPickCannotBeDone) {
  // With YCBV_05's 2024 handles the bottle cannot be grasped where it stands.
  const CliResult r = run_cli({"plan", "--task", "shelf_2", "--robot", "panda", "--pose", "0", "--seed", "1",
                               "--time-limit", "1", "--json", "--data-dir",
                               demoplan::testdata::data_dir_with_2024_bottle(DEMOPLAN_DATA_DIR)},
                              dir_);
  EXPECT_EQ(r.code, 1) << r.err;
  const Json j = one_object(r);
  EXPECT_FALSE(j["solved"].get<bool>());
  EXPECT_FALSE(j["feasible"].get<bool>());
  ASSERT_EQ(j["picks"].size(), 3u);
  EXPECT_FALSE(j["picks"][1]["feasible"].get<bool>());
  EXPECT_EQ(j["picks"][1]["object"], "YCBV_05");
  EXPECT_NE(r.err.find("pick 2 (YCBV_05) cannot be done"), std::string::npos) << r.err;
}

TEST_F(CliPlanning, BenchPrintsRowsAndWritesOmplLogs) {
  const fs::path log = dir_ / "bench.log";
  const CliResult r = run({"bench", "--tasks", "shelf_0", "--robots", "panda", "--poses", "1", "--seeds", "1-2",
                           "--time-limit", "60", "--json", "--ompl-log", log.string()});
  ASSERT_EQ(r.code, 0) << r.err;
  const Json j = one_object(r);
  ASSERT_EQ(j["rows"].size(), 2u);  // the planner's path and the shortened one
  for (const auto& row : j["rows"]) {
    for (const char* key : {"task", "robot", "planner", "runs", "solved", "success_rate", "median_time_s",
                            "mean_time_s", "median_path_length_rad", "mean_grasps"})
      EXPECT_TRUE(row.contains(key)) << key;
    EXPECT_EQ(row["runs"].get<int>(), 2);
    EXPECT_EQ(row["success_rate"].get<double>(), 1.0);
  }
  EXPECT_LT(j["rows"][1]["median_path_length_rad"].get<double>(), j["rows"][0]["median_path_length_rad"].get<double>());
  const std::string ompl = read_text(dir_ / "bench_shelf_0_panda.log");
  EXPECT_NE(ompl.find("2 planners"), std::string::npos) << ompl.substr(0, 400);
}

// OMPL's own reader of benchmark logs (Debian's ompl-demos) takes the log into its SQLite
// database under the experiment's whole name: it keeps only the last word of a name with spaces,
// so "shelf_0 panda" and "shelf_1 panda" would merge.
TEST_F(CliPlanning, OmplBenchmarkStatisticsReadsTheBenchLogUnderItsWholeName) {
  const std::string script = [] {
    for (const char* name : {"ompl_benchmark_statistics", "ompl_benchmark_statistics.py"}) {
      const std::string found = run_shell(std::string("command -v ") + name);
      if (!found.empty()) return found;
    }
    return std::string();
  }();
  if (script.empty()) GTEST_SKIP() << "ompl_benchmark_statistics is not installed (Debian: ompl-demos)";
  const fs::path log = dir_ / "stats.log", db = dir_ / "stats.db";
  // Two planners compared: four OMPL planners (each with its shortened variant) in one experiment.
  const CliResult r = run({"bench", "--tasks", "shelf_0", "--robots", "panda", "--poses", "1", "--seeds", "1",
                           "--time-limit", "60", "--compare", "guided,unguided", "--ompl-log", log.string()});
  ASSERT_EQ(r.code, 0) << r.err;
  const fs::path written = dir_ / "stats_shelf_0_panda.log";
  ASSERT_TRUE(fs::exists(written));
  const int status = std::system((shell_quote(script) + " " + shell_quote(written.string()) + " -d " +
                                  shell_quote(db.string()) + " >/dev/null 2>&1").c_str());
  ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << "the script failed on " << written;
  const std::string names = run_shell("python3 -c \"import sqlite3, sys; print(*[r[0] for r in sqlite3.connect(sys.argv[1])"
                                      ".execute('select name from experiments')])\" " + shell_quote(db.string()));
  EXPECT_EQ(names, "shelf_0-panda");
  const std::string planners = run_shell("python3 -c \"import sqlite3, sys; print(*sorted(r[0] for r in sqlite3.connect(sys.argv[1])"
                                         ".execute('select name from plannerConfigs')))\" " + shell_quote(db.string()));
  EXPECT_EQ(planners, "guided guided+shortcut unguided unguided+shortcut");
}

// bench --compare: the planners run alternately on the same seeds; every run names its planner
// and the ratio of median planning times is printed and written.
TEST_F(CliPlanning, BenchComparesGuidedAndUnguidedOnTheSameRuns) {
  const fs::path out = dir_ / "compare.json";
  const CliResult r = run({"bench", "--tasks", "shelf_0", "--robots", "panda", "--poses", "1", "--seeds", "1-2",
                           "--time-limit", "60", "--compare", "guided,unguided", "--out", out.string()});
  ASSERT_EQ(r.code, 0) << r.err;
  const Json j = Json::parse(read_text(out));
  ASSERT_EQ(j["runs"].size(), 4u);
  std::vector<std::string> order;
  for (const auto& run : j["runs"]) {
    order.push_back(run["planner"].get<std::string>() + std::to_string(run["seed"].get<int>()));
    EXPECT_TRUE(run["valid"].get<bool>()) << run.dump();
  }
  EXPECT_EQ(order, (std::vector<std::string>{"guided1", "unguided1", "guided2", "unguided2"}));
  ASSERT_EQ(j["rows"].size(), 4u);
  ASSERT_EQ(j["comparisons"].size(), 1u);
  const double ratio = j["comparisons"][0]["median_time_ratio"].get<double>();
  double guided = 0, unguided = 0;
  for (const auto& row : j["rows"]) {
    if (row["planner"] == "guided") guided = row["median_time_s"].get<double>();
    if (row["planner"] == "unguided") unguided = row["median_time_s"].get<double>();
  }
  EXPECT_NEAR(ratio, unguided / guided, 1e-9);
  EXPECT_NE(r.err.find("median planning time, unguided / guided"), std::string::npos) << r.err;
}

// bench-segments: the guided solution of shelf_0 cut into its single-state motions, each solved by
// our RRT-Connect (and OMPL's when built in) and checked; the table compares median times.
TEST_F(CliPlanning, BenchSegmentsComparesSingleStatePlanners) {
  const bool ompl = DEMOPLAN_WITH_OMPL;  // how the CLI was built
  std::vector<std::string> args{"bench-segments", "--tasks", "shelf_0", "--robots", "panda", "--poses", "1",
                                "--seeds", "1", "--time-limit", "10", "--json", "--planners",
                                ompl ? "rrtconnect,ompl-rrtconnect" : "rrtconnect"};
  const CliResult r = run(args);
  ASSERT_EQ(r.code, 0) << r.err;
  const Json j = one_object(r);
  ASSERT_EQ(j["rows"].size(), ompl ? 2u : 1u);
  ASSERT_GE(j["segments"].size(), 1u);
  for (const auto& row : j["rows"]) {
    for (const char* key : {"planner", "runs", "success", "success_rate", "median_time_s", "mean_time_s",
                            "median_path_length_rad", "median_time_ratio"})
      EXPECT_TRUE(row.contains(key)) << key;
    EXPECT_EQ(row["runs"].get<size_t>(), j["segments"].size());
    EXPECT_EQ(row["success_rate"].get<double>(), 1.0) << row["planner"];
  }
  EXPECT_EQ(j["rows"][0]["planner"], "rrtconnect");
  EXPECT_DOUBLE_EQ(j["rows"][0]["median_time_ratio"].get<double>(), 1.0);
}

TEST_F(CliPlanning, BenchSegmentsRefusesAnUnknownPlannerNamingTheOption) {
  const CliResult r = run({"bench-segments", "--tasks", "shelf_0", "--planners", "rrtconnect,ompl-rrt-star"});
  EXPECT_EQ(r.code, 2);
  EXPECT_EQ(lines(r.err).size(), 1u) << r.err;
  EXPECT_NE(r.err.find("--planners"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("ompl-rrt-star"), std::string::npos) << r.err;
  if (!DEMOPLAN_WITH_OMPL) {  // a known OMPL planner in a build without OMPL: says so
    const CliResult o = run({"bench-segments", "--tasks", "shelf_0", "--planners", "rrtconnect,ompl-rrtconnect"});
    EXPECT_EQ(o.code, 2);
    EXPECT_NE(o.err.find("built without it"), std::string::npos) << o.err;
  }
}

}  // namespace
