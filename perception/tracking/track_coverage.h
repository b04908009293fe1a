#pragma once
// How much of a part's track the tracker measured and how surely: the frames it saw the part in,
// how many of those below a confidence, and the runs of frames it did not see it in. What
// `extract` prints per part, as the GUI's Part Tracks strip draws it.
#include <string>
#include <utility>
#include <vector>

#include "perception/tracking/pose_track.h"

namespace demoplan::perception {

// A frame's confidence from which it counts as sure (below kLowConfidence it is low).
inline constexpr double kSureConfidence = 0.8;
// A part not seen in the last this many frames or more is lost for good: `extract` and the Part
// Tracks panel point it out (the operator can place it again: tracker_init.h's corrections).
inline constexpr int kLostForGoodFrames = 10;

struct TrackCoverage {
  int frames = 0;  // of the track
  int seen = 0;    // with an estimate
  int unsure = 0;  // of those, below the confidence asked
  std::vector<std::pair<int, int>> unseen;  // first and last frame of each run without an estimate

  // The first frame of the run not seen that lasts to the track's end, or -1.
  int lost_from() const { return !unseen.empty() && unseen.back().second == frames - 1 ? unseen.back().first : -1; }
  // That frame when the part was seen before it and the run is kLostForGoodFrames long or more, or -1.
  int lost_for_good_from() const {
    const int f = lost_from();
    return f > 0 && frames - f >= kLostForGoodFrames ? f : -1;
  }
};

TrackCoverage track_coverage(const std::vector<PoseSample>& samples, double sure = kSureConfidence);

// "seen in 106 of 150 frames, 9 of them below 0.8 confidence; not seen in frames 54-70, 74-91":
// at most `runs` runs listed, then how many more; a last run that lasts to the end is always
// listed (where a part was lost for good matters most).
std::string describe_coverage(const TrackCoverage& c, double sure = kSureConfidence, size_t runs = 4);

}  // namespace demoplan::perception
