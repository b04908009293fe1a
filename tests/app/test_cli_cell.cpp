// Cells as a user works with them from the command line: a cell made of files the test writes
// itself (an STL part, a box table) planned through a one-pick demonstration; the bundled
// example cells checked, their parts' grasps generated, random picks drawn and planned; and the
// cell mistakes the issue lists refused with one line naming the file and the field.
#include <cstdint>
#include <cstring>
#include <fstream>

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "tests/app/cli_suite.h"
#include "tests/support/box_stl.h"

namespace {

namespace fs = std::filesystem;
using Json = nlohmann::json;
using namespace demoplan::testing_support;
using demoplan::test::write_box_stl;

const std::string kCells = std::string(DEMOPLAN_DATA_DIR) + "/../cells";

Json pose(double x, double y, double z, double yaw = 0.0) { return {{"xyz", {x, y, z}}, {"rpy", {0.0, 0.0, yaw}}}; }

// A Panda on a table with one part of `part_mm` given by an STL the test writes.
Json own_cell(const fs::path& dir, float sx, float sy, float sz) {
  write_box_stl(dir / "part.stl", sx, sy, sz);
  return {{"format", "demoplan-cell"},
          {"version", 1},
          {"name", "test cell"},
          {"robot", {{"bundled", "panda"}, {"base", pose(0, 0, 0.75)}}},
          {"furniture", {{{"name", "table"}, {"box", {1.2, 1.0, 0.75}}, {"pose", pose(0.4, 0, 0.375)}, {"supports", "auto"}}}},
          {"parts", {{{"name", "block"}, {"mesh", "part.stl"}, {"scale", 0.001},
                      {"pose", pose(0.45, -0.2, 0.75 + sz / 2000.0 + 0.001)}}}}};
}

// Grasp the part where it rests, put it down 35 cm further and turned a quarter (at `release_z`
// when given: where the demonstrator let go of it).
Json one_pick(double z, double release_z = -1) {
  if (release_z < 0) release_z = z;
  auto matrix = [](double x, double y, double z, double yaw) {
    const double c = std::cos(yaw), s = std::sin(yaw);
    return Json{{c, -s, 0, x}, {s, c, 0, y}, {0, 0, 1, z}, {0, 0, 0, 1}};
  };
  return {{"format", "demoplan-demonstration"},
          {"version", 1},
          {"task", "test cell"},
          {"fps", 30},
          {"objects", {"block"}},
          {"events",
           {{{"frame", 20}, {"object", "block"}, {"type", "grasp"}, {"confidence", 1.0}, {"poses", {{"block", matrix(0.45, -0.2, z, 0)}}}},
            {{"frame", 60}, {"object", "block"}, {"type", "release"}, {"confidence", 1.0},
             {"poses", {{"block", matrix(0.45, 0.15, release_z, M_PI / 2)}}}}}}};
}

class CliCell : public CliSuite {
protected:
  static fs::path write(const std::string& name, const Json& j) {
    write_text(dir_ / name, j.dump(1));
    return dir_ / name;
  }
};

TEST_F(CliCell, ACellMadeOfTheUsersFilesIsPlannedAndValidated) {
  const fs::path cell = write("own.cell.json", own_cell(dir_, 40, 50, 80));
  const fs::path demo = write("own.demo.json", one_pick(0.75 + 0.04 + 0.001));
  const fs::path path = dir_ / "own.path.json";
  const CliResult r = run({"plan", "--cell", cell.string(), "--demo", demo.string(), "--seed", "1", "--time-limit", "60",
                           "--out", path.string(), "--json"});
  ASSERT_EQ(r.code, 0) << r.err;
  const Json j = Json::parse(r.out);
  EXPECT_EQ(j["cell"], cell.string());
  EXPECT_TRUE(j["solved"].get<bool>());
  EXPECT_TRUE(j["valid"].get<bool>()) << j["validation_message"];
  EXPECT_EQ(j["grasps"].get<int>(), 1);
  // The saved path, judged again from the same files.
  const CliResult v = run({"validate", path.string(), "--cell", cell.string(), "--demo", demo.string(), "--json"});
  ASSERT_EQ(v.code, 0) << v.err;
  EXPECT_TRUE(Json::parse(v.out)["valid"].get<bool>());
  // And exported for the controller, its blends checked in the cell.
  const fs::path program = dir_ / "own.csv";
  const CliResult e = run({"export", path.string(), "--cell", cell.string(), "--format", "csv", "--out", program.string(), "--json"});
  ASSERT_EQ(e.code, 0) << e.err;
  EXPECT_TRUE(fs::exists(program));
}

TEST_F(CliCell, ExampleCellsLoadCollisionFreeWithGeneratedGrasps) {
  for (const std::string name : {"ur5_workbench", "iiwa_shelf"}) {
    const CliResult r = run({"check", "--cell", kCells + "/" + name + ".json", "--seconds", "0.1", "--json"});
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_TRUE(Json::parse(r.out)["start_collision_free"].get<bool>()) << name;
  }
  const CliResult g = run({"grasps", "--cell", kCells + "/ur5_workbench.json", "--part", "bracket", "--json"});
  ASSERT_EQ(g.code, 0) << g.err;
  const Json j = Json::parse(g.out);
  ASSERT_GE(j["handles"].size(), 2u);
  for (const auto& h : j["handles"]) {
    EXPECT_EQ(h["pose"].size(), 4u);
    EXPECT_GE(h["quality"].get<double>(), 0.0);
    EXPECT_LE(h["quality"].get<double>(), 1.0);
  }
  EXPECT_GE(j["placements"].get<int>(), 3);
}

TEST_F(CliCell, RandomPicksInTheWorkbenchCellArePlannedValid) {
  const fs::path demo = dir_ / "random.demo.json";
  const std::string cell = kCells + "/ur5_workbench.json";
  const CliResult d = run({"demo", "--cell", cell, "--picks", "2", "--seed", "1", "--out", demo.string(), "--json"});
  ASSERT_EQ(d.code, 0) << d.err;
  EXPECT_EQ(Json::parse(d.out)["picks"].size(), 2u);
  const CliResult r = run({"plan", "--cell", cell, "--demo", demo.string(), "--seed", "1", "--time-limit", "60", "--json"});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_TRUE(Json::parse(r.out)["valid"].get<bool>());
}

// bench runs the protocol on a cell: one task instance per demonstration, every path validated.
TEST_F(CliCell, BenchOnACellRunsEveryDemonstration) {
  const std::string cell = kCells + "/ur5_workbench.json";
  std::vector<std::string> demos;
  for (const char* seed : {"2", "3"}) {
    demos.push_back((dir_ / ("bench_seed" + std::string(seed) + ".json")).string());
    const CliResult d = run({"demo", "--cell", cell, "--picks", "2", "--seed", seed, "--out", demos.back()});
    ASSERT_EQ(d.code, 0) << d.err;
  }
  const fs::path out = dir_ / "bench_cell.json";
  const CliResult b = run({"bench", "--cell", cell, "--demos", demos[0] + "," + demos[1], "--seeds", "1-2", "--time-limit",
                           "30", "--out", out.string(), "--json"});
  ASSERT_EQ(b.code, 0) << b.err;
  const Json rows = Json::parse(b.out)["rows"];
  ASSERT_EQ(rows.size(), 4u);  // two demonstrations, each the planner's own path and shortened
  for (const auto& row : rows) {
    EXPECT_EQ(row["robot"], "ur5") << row;
    EXPECT_EQ(row["runs"], 2) << row;
    EXPECT_EQ(row["success_rate"], 1.0) << row;
  }
  EXPECT_EQ(rows[0]["task"], "bench_seed2");
  const Json report = Json::parse(std::ifstream(out));
  EXPECT_EQ(report["cell"], cell);
  EXPECT_EQ(report["runs"].size(), 4u);
  // Without demonstrations, or with a task beside the cell, it is refused.
  EXPECT_EQ(run({"bench", "--cell", cell}).code, 2);
  EXPECT_NE(run({"bench", "--cell", cell, "--demos", demos[0], "--tasks", "shelf_1"}).code, 0);
}

TEST_F(CliCell, ABenchmarkTaskIsPlannedWithGeneratedHandles) {
  const fs::path path = dir_ / "generated.path.json";
  const std::vector<std::string> task{"--task", "shelf_1", "--robot", "panda", "--pose", "0", "--handles", "generated"};
  std::vector<std::string> plan{"plan", "--seed", "1", "--time-limit", "60", "--out", path.string(), "--json"};
  plan.insert(plan.end(), task.begin(), task.end());
  const CliResult r = run(plan);
  ASSERT_EQ(r.code, 0) << r.err;
  const Json j = Json::parse(r.out);
  EXPECT_EQ(j["handles"], "generated");
  EXPECT_TRUE(j["valid"].get<bool>());
  // One gripper close per pick. The benchmark's count may be higher: the approach to a deep
  // handle passes through the shallower ones on its line (docs/validation.md).
  EXPECT_EQ(j["gripper_closes"].get<int>(), 2);
  EXPECT_GE(j["grasps"].get<int>(), 2);
  // Against the benchmark's own start and goal: the validator does not know the handles changed.
  EXPECT_EQ(j["validated_against"], "benchmark subgoals");
  // The saved path judged again with the same handles; with the hand-made ones the part is held
  // by none of them, so it is neither grasped nor placed while it moves.
  std::vector<std::string> validate{"validate", path.string(), "--json"};
  validate.insert(validate.end(), task.begin(), task.end());
  const CliResult v = run(validate);
  ASSERT_EQ(v.code, 0) << v.err;
  EXPECT_TRUE(Json::parse(v.out)["valid"].get<bool>()) << v.out;
  EXPECT_EQ(Json::parse(v.out)["gripper_closes"].get<int>(), 2);
  validate.pop_back(), validate.pop_back();  // --handles generated
  const CliResult srdf = run(validate);
  EXPECT_FALSE(Json::parse(srdf.out)["valid"].get<bool>()) << srdf.out;
}

// One line on stderr, exit 2, naming the file and the field.
void expect_refused(const CliResult& r, const std::string& file, const std::string& field, const std::string& why) {
  EXPECT_EQ(r.code, 2) << r.err;
  const auto l = lines(r.err);
  ASSERT_FALSE(l.empty());
  EXPECT_NE(l.back().find(file), std::string::npos) << r.err;
  EXPECT_NE(l.back().find(field), std::string::npos) << r.err;
  EXPECT_NE(l.back().find(why), std::string::npos) << r.err;
}

TEST_F(CliCell, CellMistakesAreRefusedNamingFileAndField) {
  Json missing = own_cell(dir_, 40, 50, 80);
  missing["parts"][0]["mesh"] = "nowhere.stl";
  const fs::path m = write("missing.cell.json", missing);
  expect_refused(run({"check", "--cell", m.string()}), m.string(), "parts[0].mesh", "no such file");

  const fs::path wide = write("wide.cell.json", own_cell(dir_, 150, 120, 100));
  expect_refused(run({"grasps", "--cell", wide.string(), "--part", "block"}), wide.string(), "parts[0].handles", "too wide");

  Json blocked = own_cell(dir_, 40, 50, 80);
  blocked["furniture"].push_back({{"name", "post"}, {"box", {0.1, 0.1, 1.0}}, {"pose", pose(0, 0, 1.2)}});
  const fs::path b = write("blocked.cell.json", blocked);
  expect_refused(run({"check", "--cell", b.string()}), b.string(), "robot", "starts in collision");

  expect_refused(run({"plan", "--cell", m.string()}), m.string(), "", "--demo");
}

// A part let go of 5 cm above the table (a release the camera did not see land) is refused
// before planning, naming the demonstration file, the event, its frame and the part.
TEST_F(CliCell, APartReleasedInTheAirIsRefusedBeforePlanning) {
  const fs::path cell = write("own.cell.json", own_cell(dir_, 40, 50, 80));
  const fs::path demo = write("floating.demo.json", one_pick(0.75 + 0.04 + 0.001, 0.75 + 0.04 + 0.05));
  const CliResult r = run({"plan", "--cell", cell.string(), "--demo", demo.string(), "--seed", "1", "--time-limit", "60"});
  expect_refused(r, demo.string(), "events[1] (frame 60)", "block rests on no support: 50 mm above the nearest (table/");
  EXPECT_EQ(r.err.find("guided"), std::string::npos) << r.err;  // refused before the planner ran
}

}  // namespace
