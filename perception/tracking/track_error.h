#pragma once
// How far a tracker's per-frame estimates are from the truth in every frame (a synthetic video's
// truth.tracks.json): the event poses alone judge only the rests, not the carries between them.
#include "perception/tracking/pose_track.h"

namespace demoplan::perception {

struct TrackError {
  int truth_samples = 0;      // frames x parts the truth has
  int estimated_samples = 0;  // of those, with an estimate (of the same part id)
  double coverage = 0.0;      // estimated / truth samples
  // Distance of the estimated part frame's origin from the true one, mm; -1 without estimates.
  double median_translation_mm = -1.0;
  double p95_translation_mm = -1.0;
};

// Parts are matched by id (one the estimate lacks counts as never estimated); frames beyond
// either's end are left out.
TrackError track_error(const PoseTracks& estimated, const PoseTracks& truth);

}  // namespace demoplan::perception
