// The CLI as a user runs it: the real demoplan-cli binary, its exit codes, its one JSON object
// on stdout, and its one-line errors on stderr.
#include <gtest/gtest.h>

#include <algorithm>

#include <nlohmann/json.hpp>

#include "core/project/project.h"
#include "tests/app/cli_runner.h"

namespace {

namespace fs = std::filesystem;
using Json = nlohmann::json;
using namespace demoplan::testing_support;
using Result = CliResult;

class Cli : public ::testing::Test {
protected:
  void SetUp() override { work_ = make_temp_dir("demoplan_test_cli_"); }
  void TearDown() override {
    std::error_code ec;
    fs::remove_all(work_, ec);
  }
  static void TearDownTestSuite() {
    if (!broken_root_.empty()) {
      std::error_code ec;
      fs::remove_all(broken_root_, ec);
      broken_root_.clear();
    }
  }

  Result run(const std::vector<std::string>& args, const std::string& env = "") const {
    return run_cli(args, work_, env);
  }
  // Another program (ldd): its exit status and output.
  Result run_shell(const std::string& command) const { return run_command(command, work_); }

  static std::vector<std::string> check_args(const std::string& task, const std::string& robot,
                                             const std::string& pose = "0") {
    return {"check", "--task", task, "--robot", robot, "--pose", pose, "--json", "--seconds", "0.2",
            "--data-dir", DEMOPLAN_DATA_DIR};
  }

  // stdout must be exactly one JSON object on one line.
  static Json parse_one_object(const Result& r) {
    EXPECT_EQ(lines(r.out).size(), 1u) << "stdout:\n" << r.out;
    Json j;
    try {
      j = Json::parse(r.out);  // throws on anything after the first value
    } catch (const Json::exception& e) {
      ADD_FAILURE() << "stdout is not one JSON value: " << e.what() << "\n" << r.out;
      return Json::object();
    }
    EXPECT_TRUE(j.is_object()) << r.out;
    for (const char* key : {"dof", "links", "collision_pairs", "start_collision_free",
                            "goal_collision_free", "checks_per_second"})
      EXPECT_TRUE(j.contains(key)) << "missing key " << key << " in " << r.out;
    return j;
  }

  // A copy of the benchmark data whose shelf_1.json has one frame too few in objects_poses[1];
  // made on first use, shared by the suite.
  static std::string broken_data_dir() {
    if (broken_root_.empty()) {
      broken_root_ = make_temp_dir("demoplan_test_cli_data_");
      const fs::path data = broken_root_ / "gtamp";
      fs::copy(DEMOPLAN_DATA_DIR, data, fs::copy_options::recursive);
      const fs::path task = data / "tasks" / "shelf_1.json";
      Json j = Json::parse(read_text(task));
      j["objects_poses"][1].erase(j["objects_poses"][1].size() - 1);
      write_text(task, j.dump(1));
    }
    return (broken_root_ / "gtamp").string();
  }

  // A bad-input failure: exit 2, nothing on stdout, one line on stderr containing every part.
  static void expect_bad_input(const Result& r, const std::vector<std::string>& parts) {
    EXPECT_EQ(r.code, 2) << r.err;
    EXPECT_TRUE(r.out.empty()) << "stdout: " << r.out;
    EXPECT_EQ(lines(r.err).size(), 1u) << "stderr:\n" << r.err;
    for (const auto& p : parts) EXPECT_NE(r.err.find(p), std::string::npos) << "'" << p << "' not in: " << r.err;
  }

  fs::path work_;
  static inline fs::path broken_root_;
};

TEST_F(Cli, ShelfPandaIsCollisionFree) {
  const Result r = run(check_args("shelf_1", "panda"));
  ASSERT_EQ(r.code, 0) << r.err;
  const Json j = parse_one_object(r);
  EXPECT_EQ(j.value("dof", -1), 9);
  EXPECT_EQ(j.value("links", -1), 12);
  EXPECT_GT(j.value("collision_pairs", 0), 0);
  EXPECT_EQ(j.value("start_collision_free", false), true);
  EXPECT_EQ(j.value("goal_collision_free", false), true);
  EXPECT_GT(j.value("checks_per_second", 0.0), 0.0);
  // The human summary goes to stderr.
  EXPECT_NE(r.err.find("shelf_1"), std::string::npos) << r.err;
}

TEST_F(Cli, ShelfUr5) {
  const Result r = run(check_args("shelf_1", "ur5"));
  ASSERT_EQ(r.code, 0) << r.err;
  const Json j = parse_one_object(r);
  EXPECT_EQ(j.value("dof", -1), 8);
  EXPECT_GT(j.value("collision_pairs", 0), 0);
  EXPECT_EQ(j.value("start_collision_free", false), true);
  EXPECT_EQ(j.value("goal_collision_free", false), true);
}

TEST_F(Cli, WaiterKmrIiwa) {
  const Result r = run(check_args("waiter_0", "kmr_iiwa"));
  ASSERT_EQ(r.code, 0) << r.err;
  const Json j = parse_one_object(r);
  EXPECT_EQ(j.value("dof", -1), 12);
  EXPECT_GT(j.value("collision_pairs", 0), 0);
  EXPECT_EQ(j.value("start_collision_free", false), true);
  EXPECT_EQ(j.value("goal_collision_free", false), true);
}

TEST_F(Cli, WithoutJsonStdoutIsEmpty) {
  const Result r = run({"check", "--task", "shelf_1", "--robot", "panda", "--pose", "0", "--seconds",
                        "0.2", "--data-dir", DEMOPLAN_DATA_DIR});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_TRUE(r.out.empty()) << r.out;
  EXPECT_NE(r.err.find("collision-free"), std::string::npos) << r.err;
}

TEST_F(Cli, TestTaskStartsInCollision) {
  // test_0: identity poses everywhere, the two cuboids inside each other (and the robot in the
  // tunnel): the job runs and fails.
  const Result r = run(check_args("test_0", "panda"));
  EXPECT_EQ(r.code, 1) << r.err;
  const Json j = parse_one_object(r);
  EXPECT_EQ(j.value("start_collision_free", true), false);
  EXPECT_EQ(j.value("dof", -1), 9);
  EXPECT_TRUE(j.contains("start_collision")) << r.out;
}

TEST_F(Cli, BrokenTaskFileInDataDir) {
  const std::string dir = broken_data_dir();
  const Result r = run({"check", "--task", "shelf_1", "--robot", "panda", "--pose", "0", "--json",
                        "--seconds", "0.2", "--data-dir", dir});
  expect_bad_input(r, {(fs::path(dir) / "tasks" / "shelf_1.json").string(), "objects_poses[1]"});
}

TEST_F(Cli, BrokenTaskFileFromEnvironment) {
  // Without --data-dir, $DEMOPLAN_DATA_DIR chooses the data.
  const std::string dir = broken_data_dir();
  const Result r = run({"check", "--task", "shelf_1", "--robot", "panda", "--json", "--seconds", "0.2"},
                       "DEMOPLAN_DATA_DIR=" + shell_quote(dir) + " ");
  expect_bad_input(r, {(fs::path(dir) / "tasks" / "shelf_1.json").string(), "objects_poses[1]"});
}

TEST_F(Cli, UnknownTask) {
  const Result r = run(check_args("cupboard_3", "panda"));
  expect_bad_input(r, {"cupboard_3.json", "shelf_1", "waiter_0"});
}

TEST_F(Cli, UnknownRobot) {
  const Result r = run(check_args("shelf_1", "r2d2"));
  expect_bad_input(r, {"robots.json", "r2d2", "panda"});
}

TEST_F(Cli, RobotWithoutPosesForTheTask) {
  const Result r = run(check_args("waiter_0", "panda"));
  expect_bad_input(r, {"waiter_0.json", "robot_poses", "panda"});
}

TEST_F(Cli, UnknownPoseId) {
  const Result r = run(check_args("shelf_1", "panda", "42"));
  expect_bad_input(r, {"shelf_1_panda_poses.json", "poses", "42"});
}

TEST_F(Cli, UnknownOption) {
  const Result r = run({"check", "--task", "shelf_1", "--bogus"});
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_TRUE(r.out.empty()) << r.out;
  EXPECT_NE(r.err.find("--bogus"), std::string::npos) << r.err;
}

TEST_F(Cli, NoSubcommand) {
  const Result r = run({});
  EXPECT_EQ(r.code, 2) << r.err;
}

TEST_F(Cli, NonNumericPose) {
  const Result r = run({"check", "--task", "shelf_1", "--pose", "first", "--seconds", "0.2"});
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_NE(r.err.find("--pose"), std::string::npos) << r.err;
}

TEST_F(Cli, DataDirThatDoesNotExist) {
  const Result r = run({"check", "--task", "shelf_1", "--seconds", "0.2", "--data-dir",
                        (work_ / "no_such_dir").string()});
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_NE(r.err.find("no_such_dir"), std::string::npos) << r.err;
}

TEST_F(Cli, HelpExitsZero) {
  const Result r = run({"check", "--help"});
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_NE((r.out + r.err).find("--task"), std::string::npos);
}

TEST_F(Cli, VideoCommandsRunInTheirOwnExecutable) {
  // demoplan-cli maps no OpenCV library (a quarter of a second of every start); the video and
  // image commands run in demoplan-cli-video beside it, listed in the help and answering as
  // demoplan-cli.
  const Result libs = run_shell("ldd " + shell_quote(DEMOPLAN_CLI));
  ASSERT_EQ(libs.code, 0) << libs.err;
  EXPECT_EQ(libs.out.find("libopencv"), std::string::npos) << libs.out;
  EXPECT_EQ(libs.out.find("not found"), std::string::npos) << libs.out;
  const Result help = run({"--help"});
  EXPECT_EQ(help.code, 0) << help.err;
  for (const char* command : {"plan", "extract", "synth", "calibrate", "synth-board", "new", "inspect"})
    EXPECT_NE(help.out.find(std::string("\n  ") + command + " "), std::string::npos) << command << "\n" << help.out;
  const Result board = run({"board", "--out", (work_ / "board.json").string(), "--json"});
  EXPECT_EQ(board.code, 0) << board.err;
  EXPECT_TRUE(fs::exists(work_ / "board.json"));
  const Result usage = run({"extract", "--help"});
  EXPECT_EQ(usage.code, 0) << usage.err;
  EXPECT_NE(usage.out.find("Usage: demoplan-cli extract"), std::string::npos) << usage.out;
  const Result bad = run({"extract"});
  EXPECT_EQ(bad.code, 2);
  EXPECT_EQ(lines(bad.err).size(), 1u) << bad.err;
}

TEST_F(Cli, EveryCommandInTheHelpAnswersItsOwnHelp) {
  // The video commands are listed by demoplan-cli and registered in demoplan-cli-video: a command
  // listed in one and missing in the other would fail here.
  const Result help = run({"--help"});
  ASSERT_EQ(help.code, 0) << help.err;
  const std::vector<std::string> out = lines(help.out);
  const auto first = std::find(out.begin(), out.end(), "Subcommands:");
  ASSERT_NE(first, out.end()) << help.out;
  std::vector<std::string> commands;
  for (auto it = first + 1; it != out.end() && it->rfind("  ", 0) == 0; ++it)
    commands.push_back(it->substr(2, it->find(' ', 2) - 2));
  EXPECT_GE(commands.size(), 23u) << help.out;
  for (const char* command : {"plan", "place", "synth", "calibrate", "synth-board"})
    EXPECT_NE(std::find(commands.begin(), commands.end(), command), commands.end()) << command;
  for (const std::string& command : commands) {
    const Result usage = run({command, "--help"});
    EXPECT_EQ(usage.code, 0) << command << ": " << usage.err;
    EXPECT_NE(usage.out.find("Usage: demoplan-cli " + command + " "), std::string::npos) << usage.out;
  }
}

TEST_F(Cli, NewWritesAProjectTheDesktopApplicationOpens) {
  const fs::path out = work_ / "job.demoplan";
  const Result r = run({"new", "shelf_1:panda:1", "--out", out.string(), "--json", "--data-dir", DEMOPLAN_DATA_DIR});
  ASSERT_EQ(r.code, 0) << r.err;
  const Json j = Json::parse(r.out);
  const demoplan::Project p = demoplan::load_project(out.string());
  EXPECT_EQ(p.scene.task, "shelf_1");
  EXPECT_EQ(p.scene.robot, "panda");
  EXPECT_EQ(p.scene.pose, 1);
  ASSERT_EQ(j["events"].get<size_t>(), p.demonstration.events.size());
  EXPECT_EQ(p.demonstration.events.size(), 2 * p.demonstration.object_ids.size());  // each part picked once
  EXPECT_TRUE(j["deck_notes"].empty());
  EXPECT_TRUE(p.video.empty());
}

TEST_F(Cli, NewSaysWhereThePartsRideOnTheRobot) {
  const fs::path out = work_ / "waiter.demoplan";
  const Result r = run({"new", "waiter_0:kmr_iiwa:0", "--out", out.string(), "--json", "--data-dir", DEMOPLAN_DATA_DIR});
  ASSERT_EQ(r.code, 0) << r.err;
  const Json j = Json::parse(r.out);
  ASSERT_EQ(j["deck_notes"].size(), 3u) << r.out;  // YCBV_02, 03 and 05 ride on the deck
  EXPECT_NE(r.err.find("on the robot's deck: YCBV_05 on kmr_link"), std::string::npos) << r.err;
}

TEST_F(Cli, NewRefusesABadSceneOrFile) {
  const std::string out = (work_ / "x.demoplan").string();
  for (const std::string spec : {"shelf_1:panda", "shelf_1:panda:x", "shelf_1::1"}) {
    const Result r = run({"new", spec, "--out", out, "--data-dir", DEMOPLAN_DATA_DIR});
    EXPECT_EQ(r.code, 2) << spec << ": " << r.err;
    EXPECT_NE(r.err.find("TASK:ROBOT:POSE"), std::string::npos) << r.err;
  }
  const Result task = run({"new", "shelf_9:panda:0", "--out", out, "--data-dir", DEMOPLAN_DATA_DIR});
  EXPECT_EQ(task.code, 2) << task.err;
  EXPECT_NE(task.err.find("shelf_9"), std::string::npos) << task.err;
  write_text(work_ / "camera.json", R"({"format": "demoplan-camera", "version": 7})");
  const Result camera = run({"new", "shelf_1:panda:1", "--out", out, "--camera", (work_ / "camera.json").string(),
                             "--data-dir", DEMOPLAN_DATA_DIR});
  EXPECT_EQ(camera.code, 2) << camera.err;
  EXPECT_NE(camera.err.find("camera.json"), std::string::npos) << camera.err;
  EXPECT_NE(camera.err.find("version"), std::string::npos) << camera.err;
  EXPECT_FALSE(fs::exists(out));  // nothing written after a refusal
}

}  // namespace

// `part`: where a user's part rests, from its mesh alone.
TEST_F(Cli, PartListsWhereABenchmarkPartRests) {
  const Result r = run({"part", std::string(DEMOPLAN_DATA_DIR) + "/objects/ycbv/meshes/obj_000002.obj", "--scale", "0.001",
                        "--json"});
  ASSERT_EQ(r.code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  ASSERT_GE(j["placements"].size(), 6u);
  const auto& first = j["placements"][0];
  EXPECT_GT(std::abs(first["normal"][0].get<double>()), 0.99);
  EXPECT_GT(first["margin_m"].get<double>(), 0.04);
  EXPECT_EQ(first["part_on_plane"].size(), 16u);
  EXPECT_GE(first["polygon"].size(), 3u);
}

TEST_F(Cli, PartRefusesAMissingMeshAndABadScale) {
  expect_bad_input(run({"part", "no_such_part.stl"}), {"no_such_part.stl"});
  expect_bad_input(run({"part", std::string(DEMOPLAN_DATA_DIR) + "/objects/ycbv/meshes/obj_000002.obj", "--scale", "-1"}),
                   {"obj_000002.obj", "--scale"});
}
