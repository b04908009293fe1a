// --from tracks and evaluate-tracks as a user runs them: a benchmark task planned from its pose
// tracks alone, and the detected events judged against the labels.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "tests/app/cli_suite.h"

namespace {

namespace fs = std::filesystem;
using Json = nlohmann::json;
using namespace demoplan::testing_support;

class CliTracks : public CliSuite {};

TEST_F(CliTracks, EvaluateTracksFindsTheLabelledPicksOfShelf1) {
  const CliResult r = run({"evaluate-tracks", "--task", "shelf_1", "--json"});
  ASSERT_EQ(r.code, 0) << r.err;
  const Json j = Json::parse(r.out);
  for (const char* key : {"events_true", "events_detected", "matched_2", "matched_5", "precision_2", "recall_2",
                          "precision_5", "recall_5", "median_signed_offset_frames", "sequence_correct",
                          "rest_median_mm", "rest_max_mm", "rest_median_deg", "rest_max_deg"})
    EXPECT_TRUE(j.contains(key)) << key << " in " << r.out;
  EXPECT_TRUE(j["sequence_correct"].get<bool>()) << r.out;
  EXPECT_EQ(j["sequence_detected"], Json({"YCBV_05", "YCBV_02"}));
  EXPECT_EQ(j["events_detected"].get<int>(), 4);
  EXPECT_GE(j["recall_5"].get<double>(), 0.75);
  EXPECT_LT(j["rest_median_mm"].get<double>(), 15.0);
}

TEST_F(CliTracks, PlanFromTracksIsValid) {
  const CliResult r = run({"plan", "--task", "shelf_1", "--robot", "panda", "--pose", "0", "--from", "tracks", "--seed",
                           "1", "--time-limit", "60", "--json"});
  ASSERT_EQ(r.code, 0) << r.err;
  const Json j = Json::parse(r.out);
  EXPECT_TRUE(j["solved"].get<bool>());
  EXPECT_TRUE(j["valid"].get<bool>()) << j["validation_message"];
  EXPECT_EQ(j["grasps"].get<int>(), 2);
}

TEST_F(CliTracks, AnUnknownSourceIsRefusedNamingTheOption) {
  const CliResult r = run({"plan", "--task", "shelf_1", "--from", "labels"});
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("--from"), std::string::npos) << r.err;
}

}  // namespace
