#pragma once
// The Demonstration an extraction produces: a grasp and a release per carry, and at every
// event the pose of every planning part, the robust average of its samples over the rest
// interval the event falls in (from the end of its previous motion to the start of its next).
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "core/demo/demonstration.h"
#include "perception/events/contact_detector.h"
#include "perception/tracking/pose_track.h"

namespace demoplan::perception {

// [first, last] frames of the rest of a part around `frame`; nullopt when it moves then.
std::optional<std::pair<int, int>> rest_interval(const std::vector<MotionInterval>& motions, int frame, int frames);

// Robust average of the samples in [first, last] the detector trusts (usable_samples; of all
// valid ones when it trusts none); nullopt when none is valid.
std::optional<Pose> rest_pose(const std::vector<PoseSample>& samples, int first, int last,
                              const ContactDetectorOptions& options = {});

// `warnings` receives one line per part pose that had to be guessed (a part never seen at
// rest around an event, a carry never seen to end).
Demonstration build_demonstration(const PoseTracks& tracks, const ContactAnalysis& contacts, const std::string& task,
                                  const ContactDetectorOptions& options = {},
                                  std::vector<std::string>* warnings = nullptr);

}  // namespace demoplan::perception
