// demoplan-cli export as a user runs it: a path saved from real configurations of a benchmark
// scene, every format, the one JSON object on stdout, and one-line errors with exit 2.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <regex>

#include "tests/app/cli_runner.h"
#include "tests/core/transition_path.h"

namespace {

namespace fs = std::filesystem;
using Json = nlohmann::json;
using namespace demoplan::testing_support;
using Result = CliResult;

size_t line_count(const std::string& s) { return lines(s).size(); }

class CliExport : public ::testing::Test {
protected:
  static void SetUpTestSuite() {
    root_ = fs::temp_directory_path() / ("demoplan_test_cli_export_" + std::to_string(::getpid()));
    fs::create_directories(root_);
    for (const auto& [task, robot] : {std::pair{"shelf_1", "panda"}, std::pair{"shelf_1", "ur5"}, std::pair{"waiter_0", "kmr_iiwa"}})
      demoplan::save_path((root_ / (std::string(robot) + ".json")).string(),
                          demoplan::testing_support::benchmark_transition_path(DEMOPLAN_DATA_DIR, task, robot).path);
  }
  static void TearDownTestSuite() { fs::remove_all(root_); }

  Result run(const std::vector<std::string>& args) const { return run_cli(args, root_); }
  static std::vector<std::string> args(const std::string& robot, const std::string& format, const std::string& out) {
    return {"export", (root_ / (robot + ".json")).string(), "--robot", robot, "--format", format, "--out",
            (root_ / out).string(), "--json", "--data-dir", DEMOPLAN_DATA_DIR};
  }
  static void expect_bad_input(const Result& r, const std::vector<std::string>& parts) {
    EXPECT_EQ(r.code, 2) << r.err;
    EXPECT_TRUE(r.out.empty()) << r.out;
    EXPECT_EQ(line_count(r.err), 1u) << r.err;
    for (const auto& p : parts) EXPECT_NE(r.err.find(p), std::string::npos) << "'" << p << "' not in: " << r.err;
  }
  static inline fs::path root_;
};

TEST_F(CliExport, EveryFormatWritesItsFilesAndReports) {
  struct Case {
    std::string robot, format, out;
    std::vector<std::string> extra;
  };
  const std::vector<Case> cases{{"ur5", "urscript", "ur5.script", {}},
                                {"ur5", "urscript", "ur5_servoj.script", {"--servoj", "--rate", "500"}},
                                {"ur5", "krl", "pick.src", {}},
                                {"kmr_iiwa", "sunrise", "Pick.java", {}},
                                {"panda", "franka", "panda_franka.json", {}},
                                {"kmr_iiwa", "ros-yaml", "kmr.yaml", {"--rate", "50"}},
                                {"panda", "csv", "panda.csv", {}}};
  for (const Case& c : cases) {
    SCOPED_TRACE(c.format + " " + c.robot);
    auto a = args(c.robot, c.format, c.out);
    a.insert(a.end(), c.extra.begin(), c.extra.end());
    const Result r = run(a);
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_EQ(line_count(r.out), 1u) << r.out;
    const Json j = Json::parse(r.out);
    for (const char* key : {"duration_s", "samples", "peak_velocity_ratio", "peak_acceleration_ratio",
                            "trapezoid_ratio", "files", "check_ok"})
      EXPECT_TRUE(j.contains(key)) << key;
    EXPECT_TRUE(j["check_ok"].get<bool>());
    EXPECT_GT(j["duration_s"].get<double>(), 0.5);
    EXPECT_LE(j["peak_velocity_ratio"].get<double>(), 1.0);
    EXPECT_LE(j["peak_acceleration_ratio"].get<double>(), 1.0);
    EXPECT_GT(j["trapezoid_ratio"].get<double>(), 0.5);
    for (const auto& f : j["files"]) EXPECT_TRUE(fs::exists(f.get<std::string>())) << f;
    EXPECT_NE(r.err.find("duration"), std::string::npos);
  }
  EXPECT_TRUE(fs::exists(root_ / "pick.dat"));
}

// A path the planner produced (shortened, with repeated configurations at the grasps) exports in
// the formats of both fixed-base robots and passes the checker.
TEST_F(CliExport, PlannedPathExports) {
  for (const std::string robot : {"panda", "ur5"}) {
    SCOPED_TRACE(robot);
    const std::string planned = (root_ / ("planned_" + robot + ".json")).string();
    const Result p = run({"plan", "--task", "shelf_1", "--robot", robot, "--pose", "1", "--seed", "1", "--time-limit",
                          "60", "--out", planned, "--json", "--data-dir", DEMOPLAN_DATA_DIR});
    ASSERT_EQ(p.code, 0) << p.err;
    ASSERT_TRUE(Json::parse(p.out)["valid"].get<bool>()) << p.out;
    for (const std::string format : {"csv", robot == "panda" ? "franka" : "urscript"}) {
      SCOPED_TRACE(format);
      const Result r = run({"export", planned, "--robot", robot, "--format", format, "--out",
                            (root_ / ("planned_" + robot + "." + format)).string(), "--json", "--data-dir",
                            DEMOPLAN_DATA_DIR});
      ASSERT_EQ(r.code, 0) << r.err;
      const Json j = Json::parse(r.out);
      EXPECT_TRUE(j["check_ok"].get<bool>()) << r.out;
      EXPECT_LE(j["peak_velocity_ratio"].get<double>(), 1.0);
      EXPECT_LE(j["peak_acceleration_ratio"].get<double>(), 1.0);
    }
  }
}

TEST_F(CliExport, PathBeyondAJointLimit) {
  Json path = Json::parse(read_text(root_ / "panda.json"));
  path["waypoints"][3]["q"][1] = 1.9;
  const fs::path file = root_ / "beyond.json";
  std::ofstream(file) << path.dump();
  auto a = args("panda", "csv", "x.csv");
  a[1] = file.string();
  expect_bad_input(run(a), {"beyond.json", "waypoints[3].q[1]", "panda_joint2", "beyond its limit"});
}

TEST_F(CliExport, RobotWithoutVelocityLimits) {
  // A copy of the data whose Panda URDF gives joint 4 no velocity limit.
  const fs::path data = root_ / "gtamp";
  fs::copy(DEMOPLAN_DATA_DIR, data, fs::copy_options::recursive);
  const fs::path urdf = data / "robots" / "franka_panda" / "panda.urdf";
  std::string text = read_text(urdf);
  text = std::regex_replace(text, std::regex(R"(lower="-3.1416" upper="0.0" velocity="2.1750")"),
                            R"(lower="-3.1416" upper="0.0" velocity="0")");
  std::ofstream(urdf) << text;
  auto a = args("panda", "csv", "x.csv");
  a.back() = data.string();
  expect_bad_input(run(a), {"panda.urdf", "panda_joint4", "velocity"});
}

TEST_F(CliExport, FormatThatDoesNotFitTheRobot) {
  expect_bad_input(run(args("kmr_iiwa", "krl", "kmr.src")), {"kmr.src", "mobile base"});
  expect_bad_input(run(args("panda", "urscript", "p.script")), {"p.script", "6-axis"});
}

TEST_F(CliExport, RobotOtherThanThePathsAndUnknownFormat) {
  auto a = args("panda", "csv", "x.csv");
  a[3] = "ur5";
  expect_bad_input(run(a), {"panda.json", "robot", "ur5"});
  const Result r = run(args("panda", "gcode", "x.nc"));
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("gcode"), std::string::npos) << r.err;
}

}  // namespace
