// The per-frame error of a tracker's estimates against a synthetic video's true tracks.
#include <gtest/gtest.h>

#include "perception/tracking/track_error.h"

using namespace demoplan;
using namespace demoplan::perception;

namespace {

PoseTracks tracks(const std::vector<std::string>& ids, int frames) {
  PoseTracks t;
  t.object_ids = ids;
  t.planning.assign(ids.size(), true);
  t.resize(frames);
  return t;
}

void set(PoseTracks& t, size_t k, int f, double x) {
  t.samples[k][f].valid = true;
  t.samples[k][f].confidence = 1.0;
  t.samples[k][f].pose = Pose::Identity();
  t.samples[k][f].pose.translation().x() = x;
}

}  // namespace

// Matched by id whatever the order; a part or frame not estimated counts in the coverage only.
TEST(TrackError, MedianAnd95thPercentileOverTheEstimatedTruePoses) {
  PoseTracks truth = tracks({"a", "b"}, 10), estimated = tracks({"b", "a"}, 10);
  for (int f = 0; f < 10; ++f) set(truth, 0, f, 0.0), set(truth, 1, f, 1.0);
  // Part a estimated (mm off): 1, 2, ..., 10 in frames 0-9; part b only in frames 0-4, 50 mm off.
  for (int f = 0; f < 10; ++f) set(estimated, 1, f, (f + 1) * 1e-3);
  for (int f = 0; f < 5; ++f) set(estimated, 0, f, 1.05);
  const TrackError e = track_error(estimated, truth);
  EXPECT_EQ(e.truth_samples, 20);
  EXPECT_EQ(e.estimated_samples, 15);
  EXPECT_DOUBLE_EQ(e.coverage, 0.75);
  // Sorted: 1..10, then 50 five times: the median is the 8th of 15, the 95th percentile the last.
  EXPECT_NEAR(e.median_translation_mm, 8.0, 1e-9);
  EXPECT_NEAR(e.p95_translation_mm, 50.0, 1e-9);
}

TEST(TrackError, NothingEstimatedHasNoError) {
  PoseTracks truth = tracks({"a"}, 3), estimated = tracks({"other"}, 3);
  for (int f = 0; f < 3; ++f) set(truth, 0, f, 0.0), set(estimated, 0, f, 0.0);
  const TrackError e = track_error(estimated, truth);
  EXPECT_EQ(e.truth_samples, 3);
  EXPECT_EQ(e.estimated_samples, 0);
  EXPECT_DOUBLE_EQ(e.coverage, 0.0);
  EXPECT_LT(e.median_translation_mm, 0.0);
}
