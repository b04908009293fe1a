// demoplan-cli place and merge as a user (or a Slurm job array) runs them: the JSON keys,
// shards merged into the ranking of one run, a heat map, a region where nothing fits, and bad
// input refused with exit 2 and one line naming the argument or file.
#include <fstream>

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "tests/app/cli_suite.h"

namespace {

using Json = nlohmann::json;
using namespace demoplan::testing_support;

class CliPlacement : public CliSuite {};

const std::vector<std::string> kSearch{"place", "--task", "shelf_1", "--robot", "panda", "--region",
                                       "0.1:0.5,0.0:0.4,-3.14159:3.14159", "--samples", "6", "--time-limit", "20"};

std::vector<std::string> with(std::vector<std::string> args, const std::vector<std::string>& more) {
  args.insert(args.end(), more.begin(), more.end());
  return args;
}

Json read(const fs::path& file) {
  std::ifstream in(file);
  return Json::parse(in);
}

// What a ranking is: the candidates in order with what decides their place.
std::vector<std::tuple<int, bool, double, Json>> ranking(const Json& result) {
  std::vector<std::tuple<int, bool, double, Json>> out;
  for (const auto& c : result["candidates"])
    out.emplace_back(c["index"].get<int>(), c["feasible"].get<bool>(), c["success_rate"].get<double>(), c["cycle_time_s"]);
  return out;
}

}  // namespace

TEST_F(CliPlacement, ShardsMergeIntoTheRankingOfOneRun) {
  const fs::path single = dir_ / "single.json", map = dir_ / "map.svg";
  const CliResult one = run(with(kSearch, {"--seeds", "1", "--jobs", "2", "--out", single.string(), "--heat-map", map.string(), "--json"}));
  ASSERT_EQ(one.code, 0) << one.err;
  const Json j = Json::parse(one.out);
  ASSERT_EQ(j["candidates"].size(), 6u);
  for (const auto& c : j["candidates"]) {
    for (const char* key : {"base_pose", "feasible", "reason", "success_rate", "median_time_s", "cycle_time_s"})
      EXPECT_TRUE(c.contains(key)) << key;
    for (const char* key : {"x", "y", "z", "yaw"}) EXPECT_TRUE(c["base_pose"].contains(key)) << key;
    EXPECT_EQ(c["feasible"].get<bool>(), c["reason"].get<std::string>().empty());
  }
  ASSERT_FALSE(j["ranking"].empty()) << one.err;
  EXPECT_EQ(j["furniture"].size(), 2u);  // shelf_1's table and shelf, outlined for the heat map
  const Json& best = j["candidates"][0];
  EXPECT_EQ(j["ranking"][0], best["index"]);
  EXPECT_GT(best["success_rate"].get<double>(), 0.0);
  EXPECT_GT(best["cycle_time_s"].get<double>(), 2.0);
  // Best first: no candidate with as high a success rate has a shorter cycle.
  for (const auto& c : j["candidates"]) {
    if (c["success_rate"] == best["success_rate"]) EXPECT_GE(c["cycle_time_s"].get<double>(), best["cycle_time_s"].get<double>());
  }
  std::ifstream svg(map);
  const std::string drawing((std::istreambuf_iterator<char>(svg)), std::istreambuf_iterator<char>());
  EXPECT_NE(drawing.find("id=\"samples\""), std::string::npos);
  EXPECT_NE(drawing.find("cycle time (s)"), std::string::npos);

  std::vector<std::string> parts;
  for (int s = 1; s <= 3; ++s) {
    parts.push_back((dir_ / ("place-" + std::to_string(s) + ".json")).string());
    const CliResult r = run(with(kSearch, {"--seeds", "1", "--shard", std::to_string(s) + "/3", "--out", parts.back()}));
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_EQ(read(parts.back())["candidates"].size(), 2u);
  }
  const fs::path merged = dir_ / "merged.json";
  const CliResult m = run_cli({"merge", parts[2], parts[0], parts[1], "--out", merged.string(), "--json"}, dir_);
  ASSERT_EQ(m.code, 0) << m.err;
  EXPECT_EQ(ranking(read(merged)), ranking(read(single)));
  EXPECT_EQ(read(merged)["ranking"], read(single)["ranking"]);
  EXPECT_EQ(read(merged)["furniture"], read(single)["furniture"]);

  // A shard of another search, or one given twice, is refused naming the file.
  const fs::path other = dir_ / "other-2.json";
  ASSERT_EQ(run(with(kSearch, {"--shard", "2/3", "--seeds", "2", "--out", other.string()})).code, 0);
  const CliResult foreign = run_cli({"merge", parts[0], other.string(), parts[2], "--out", (dir_ / "x.json").string()}, dir_);
  EXPECT_EQ(foreign.code, 2);
  EXPECT_EQ(lines(foreign.err).size(), 1u) << foreign.err;
  EXPECT_NE(foreign.err.find(other.string()), std::string::npos) << foreign.err;
  const CliResult missing = run_cli({"merge", parts[0], parts[1], "--out", (dir_ / "x.json").string()}, dir_);
  EXPECT_EQ(missing.code, 2);
  EXPECT_NE(missing.err.find("shard 3 of 3 is missing"), std::string::npos) << missing.err;
}

TEST_F(CliPlacement, ARegionWhereNothingFitsGivesAnEmptyRankingAndSaysWhy) {
  const CliResult r = run({"place", "--task", "shelf_1", "--robot", "panda", "--region", "4:5,4:5,0:1", "--samples",
                           "4", "--seeds", "1", "--json"});
  EXPECT_EQ(r.code, 1) << r.err;
  const Json j = Json::parse(r.out);
  EXPECT_TRUE(j["ranking"].empty());
  EXPECT_EQ(j["feasible"].get<int>(), 0);
  EXPECT_NE(j["message"].get<std::string>().find("no base pose of the 4 in the region can do every pick"),
            std::string::npos) << j["message"];
  EXPECT_NE(r.err.find("out of reach"), std::string::npos) << r.err;
}

TEST_F(CliPlacement, BadInputExitsTwoNamingTheArgument) {
  const std::vector<std::pair<std::vector<std::string>, std::string>> cases{
      {{"place", "--task", "shelf_1", "--region", "1:0,0:1,0:1"}, "--region"},
      {{"place", "--task", "shelf_1", "--region", "0:1,0.2:0.2,0:1"}, "empty"},
      {{"place", "--task", "shelf_1", "--region", "0:1,0:1,0:1", "--shard", "5/4"}, "--shard"},
      {{"place", "--task", "shelf_1", "--region", "0:1,0:1,0:1", "--shard", "two"}, "--shard"},
      {{"place", "--task", "shelf_1", "--robot", "kmr_iiwa", "--region", "0:1,0:1,0:1"}, "mobile"},
  };
  for (const auto& [args, named] : cases) {
    const CliResult r = run(args);
    EXPECT_EQ(r.code, 2) << args.back() << ": " << r.err;
    EXPECT_EQ(lines(r.err).size(), 1u) << r.err;
    EXPECT_NE(r.err.find(named), std::string::npos) << r.err;
  }
  const CliResult none = run_cli({"merge", (dir_ / "absent.json").string(), "--out", (dir_ / "x.json").string()}, dir_);
  EXPECT_EQ(none.code, 2);
  EXPECT_NE(none.err.find("absent.json"), std::string::npos) << none.err;
}
