#pragma once
// Per-frame part poses for display, without lag at grasps and releases: constant at the rest
// pose while a part rests; while it moves, a centred average of its samples within the motion
// (never across its ends), with frames where it was not seen interpolated.
#include "perception/events/contact_detector.h"
#include "perception/tracking/pose_track.h"

namespace demoplan::perception {

PoseTracks smooth_tracks(const PoseTracks& raw, const ContactAnalysis& contacts, const ContactDetectorOptions& options = {},
                         int half_window = 2);

}  // namespace demoplan::perception
