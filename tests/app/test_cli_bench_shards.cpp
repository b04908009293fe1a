// demoplan-cli bench --shard I/N and merge as a user (or a Slurm job array) runs them: three shards
// merged give the runs and rows of one unsharded bench, in its order, and a file figure reads; bad
// shards and files that do not belong together are refused with exit 2 and one line.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "tests/app/cli_suite.h"

namespace {

using Json = nlohmann::json;
using namespace demoplan::testing_support;

// 4 runs: shelf_0 with the Panda from two base poses, two seeds each.
const std::vector<std::string> kBench{"bench", "--tasks", "shelf_0", "--robots", "panda", "--poses", "0-1",
                                      "--seeds", "1-2", "--time-limit", "20"};
constexpr int kShards = 3;

std::vector<std::string> with(std::vector<std::string> args, const std::vector<std::string>& more) {
  args.insert(args.end(), more.begin(), more.end());
  return args;
}

Json read(const fs::path& file) { return Json::parse(read_text(file)); }

// The fields of each element of `list` named by `keys`: what a run or row is, without its timing.
std::vector<Json> fields(const Json& list, const std::vector<const char*>& keys) {
  std::vector<Json> out;
  for (const auto& item : list) {
    Json picked = Json::object();
    for (const char* key : keys) picked[key] = item.at(key);
    out.push_back(picked);
  }
  return out;
}
const std::vector<const char*> kRunKeys{"task", "robot", "pose", "seed", "planner", "solved", "valid"};
const std::vector<const char*> kRowKeys{"task", "robot", "planner", "runs", "solved"};

std::vector<std::string> keys_of(const Json& j) {
  std::vector<std::string> out;
  for (const auto& [key, value] : j.items()) out.push_back(key);
  return out;
}

class CliBenchShards : public CliSuite {
protected:
  // The benchmark run once unsharded and once as kShards shards, shared by the tests.
  static const fs::path& unsharded() {
    static const fs::path file = [] {
      const fs::path f = dir_ / "single.json";
      const CliResult r = run(with(kBench, {"--jobs", "2", "--out", f.string()}));
      EXPECT_EQ(r.code, 0) << r.err;
      return f;
    }();
    return file;
  }
  static const std::vector<std::string>& shards() {
    static const std::vector<std::string> files = [] {
      std::vector<std::string> out;
      for (int s = 1; s <= kShards; ++s) {
        out.push_back((dir_ / ("bench-" + std::to_string(s) + ".json")).string());
        const CliResult r = run(with(kBench, {"--shard", std::to_string(s) + "/" + std::to_string(kShards), "--out", out.back()}));
        EXPECT_EQ(r.code, 0) << r.err;
      }
      return out;
    }();
    return files;
  }
  static void expect_refused(const CliResult& r, const std::string& named) {
    EXPECT_EQ(r.code, 2) << r.err;
    EXPECT_EQ(lines(r.err).size(), 1u) << r.err;
    EXPECT_NE(r.err.find(named), std::string::npos) << r.err;
  }
};

}  // namespace

TEST_F(CliBenchShards, ShardsMergeIntoTheRunsAndRowsOfOneBench) {
  const Json single = read(unsharded());
  ASSERT_EQ(single["runs"].size(), 4u);
  EXPECT_EQ(single["shard"], Json({{"index", 1}, {"count", 1}}));
  EXPECT_EQ(single["run_count"], 4);
  for (const char* key : {"tasks", "robots", "poses", "seeds", "planners", "time_limit_s", "from", "handles"})
    EXPECT_TRUE(single["arguments"].contains(key)) << key;
  // Shard s runs every third run of the list, from the s-th.
  const std::vector<std::string>& parts = shards();
  for (int s = 1; s <= kShards; ++s) {
    const Json part = read(parts[static_cast<size_t>(s - 1)]);
    EXPECT_EQ(part["shard"], Json({{"index", s}, {"count", kShards}})) << s;
    EXPECT_EQ(part["run_count"], 4);
    EXPECT_EQ(part["arguments"], single["arguments"]);
    EXPECT_EQ(part["runs"][0]["index"], s - 1);
  }
  EXPECT_EQ(read(parts[0])["runs"].size(), 2u);

  const fs::path merged_file = dir_ / "merged.json";
  const CliResult m = run_cli({"merge", parts[2], parts[0], parts[1], "--out", merged_file.string(), "--json"}, dir_);
  ASSERT_EQ(m.code, 0) << m.err;
  EXPECT_EQ(lines(m.out).size(), 1u) << m.out;
  EXPECT_EQ(Json::parse(m.out)["runs"], 4);
  EXPECT_NE(m.err.find("guided+shortcut"), std::string::npos) << m.err;  // bench's table
  const Json merged = read(merged_file);
  EXPECT_EQ(fields(merged["runs"], kRunKeys), fields(single["runs"], kRunKeys));
  EXPECT_EQ(fields(merged["rows"], kRowKeys), fields(single["rows"], kRowKeys));
  EXPECT_EQ(keys_of(merged), keys_of(single));
  EXPECT_EQ(merged["shard"], single["shard"]);
  EXPECT_EQ(merged["arguments"], single["arguments"]);

  const CliResult f = run_cli({"figure", merged_file.string(), "--out", (dir_ / "fig.svg").string(), "--json"}, dir_);
  if (f.code == 2 && f.err.find("without Qt 6") != std::string::npos) return;  // nothing to draw with
  ASSERT_EQ(f.code, 0) << f.err;
  EXPECT_EQ(Json::parse(f.out)["planners"], Json({"guided", "guided+shortcut"}));
  EXPECT_EQ(Json::parse(f.out)["robots"], Json({"panda"}));
}

TEST_F(CliBenchShards, BadShardsAndFilesThatDoNotBelongTogetherAreRefused) {
  expect_refused(run(with(kBench, {"--shard", "4/3"})), "--shard");
  expect_refused(run(with(kBench, {"--shard", "two"})), "--shard");

  const std::vector<std::string>& parts = shards();
  const std::string out = (dir_ / "x.json").string();
  const fs::path placement = dir_ / "place-1.json";
  write_text(placement, Json({{"format", "demoplan-placement"}, {"version", 1}}).dump());
  expect_refused(run_cli({"merge", parts[0], placement.string(), parts[2], "--out", out}, dir_), placement.string());
  const CliResult missing = run_cli({"merge", parts[0], parts[1], "--out", out}, dir_);
  expect_refused(missing, "shard 3 of 3 is missing");
  expect_refused(run_cli({"merge", parts[0], parts[1], parts[1], "--out", out}, dir_), "shard 2 is also in");
  // A shard of another benchmark (other seeds), and a file from before --shard.
  Json other = read(parts[1]);
  other["arguments"]["seeds"] = Json({3, 4});
  const fs::path other_file = dir_ / "other-2.json";
  write_text(other_file, other.dump());
  expect_refused(run_cli({"merge", parts[0], other_file.string(), parts[2], "--out", out}, dir_), other_file.string());
  Json old = read(parts[1]);
  old.erase("arguments");
  const fs::path old_file = dir_ / "old.json";
  write_text(old_file, old.dump());
  expect_refused(run_cli({"merge", old_file.string(), "--out", out}, dir_), "arguments");
  EXPECT_FALSE(fs::exists(out));
}
