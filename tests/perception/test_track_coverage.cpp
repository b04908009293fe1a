// How much of a track the tracker measured: frames seen, those below the sure confidence, the
// runs of frames not seen, and the line `extract` prints from them.
#include <gtest/gtest.h>

#include "perception/tracking/track_coverage.h"

using namespace demoplan::perception;

namespace {

std::vector<PoseSample> track(const std::string& pattern) {
  // '#': seen surely, '+': seen below the sure confidence, '.': not seen.
  std::vector<PoseSample> out(pattern.size());
  for (size_t f = 0; f < pattern.size(); ++f) {
    out[f].valid = pattern[f] != '.';
    out[f].confidence = pattern[f] == '#' ? 1.0 : 0.5;
  }
  return out;
}

TEST(TrackCoverage, CountsTheFramesSeenAndTheRunsNotSeen) {
  const TrackCoverage c = track_coverage(track("..##+#...#++.#"));
  EXPECT_EQ(c.frames, 14);
  EXPECT_EQ(c.seen, 8);
  EXPECT_EQ(c.unsure, 3);
  ASSERT_EQ(c.unseen.size(), 3u);
  EXPECT_EQ(c.unseen[0], std::make_pair(0, 1));
  EXPECT_EQ(c.unseen[1], std::make_pair(6, 8));
  EXPECT_EQ(c.unseen[2], std::make_pair(12, 12));
  EXPECT_EQ(describe_coverage(c), "seen in 8 of 14 frames, 3 of them below 0.8 confidence; not seen in frames 0-1, 6-8, 12");
  EXPECT_EQ(describe_coverage(c, kSureConfidence, 2), "seen in 8 of 14 frames, 3 of them below 0.8 confidence; not seen in "
                                                      "frames 0-1, 6-8 and 1 more run");
  EXPECT_NE(describe_coverage(c, kSureConfidence, 1).find("and 2 more runs"), std::string::npos);
}

TEST(TrackCoverage, APartLostForGoodIsListedWhereItWasLostThoughTheListIsCut) {
  const TrackCoverage c = track_coverage(track("#.#.#.#.#...."));
  EXPECT_EQ(c.lost_from(), 9);
  EXPECT_EQ(describe_coverage(c, kSureConfidence, 3), "seen in 5 of 13 frames; not seen in frames 1, 3, 2 more runs and 9-12");
  EXPECT_EQ(describe_coverage(c, kSureConfidence, 5), "seen in 5 of 13 frames; not seen in frames 1, 3, 5, 7, 9-12");
  EXPECT_EQ(track_coverage(track("#.#")).lost_from(), -1);
  EXPECT_EQ(track_coverage(track("##.")).lost_from(), 2);
  EXPECT_EQ(track_coverage(track("...")).lost_from(), 0);
  // For good: seen before, and not for kLostForGoodFrames frames or more.
  EXPECT_EQ(track_coverage(track("##" + std::string(kLostForGoodFrames, '.'))).lost_for_good_from(), 2);
  EXPECT_EQ(track_coverage(track("##" + std::string(kLostForGoodFrames - 1, '.'))).lost_for_good_from(), -1);
  EXPECT_EQ(track_coverage(track(std::string(kLostForGoodFrames, '.'))).lost_for_good_from(), -1);
}

TEST(TrackCoverage, AFullySeenTrackSaysSoAlone) {
  const TrackCoverage c = track_coverage(track("#####"));
  EXPECT_TRUE(c.unseen.empty());
  EXPECT_EQ(c.unsure, 0);
  EXPECT_EQ(describe_coverage(c), "seen in 5 of 5 frames");
  EXPECT_EQ(describe_coverage(track_coverage(track("##.##"))), "seen in 4 of 5 frames; not seen in frame 2");
}

}  // namespace
