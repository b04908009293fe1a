#pragma once
// 6D estimates from a BOP results file (e.g. CosyPose) in the pose tracks: they fill the frames
// where no marker gave a pose, with a confidence of score * weight.
#include <string>
#include <vector>

#include "perception/importers/bop_csv.h"
#include "perception/tracking/pose_track.h"

namespace demoplan::perception {

// `source` names the file in errors: a detection beyond the video's last frame is bad input
// (InputError naming its line); one of a model no tracked part is made of is skipped with a
// warning. Returns the number of samples added.
int fuse_bop_detections(PoseTracks& tracks, const std::vector<BopDetection>& detections, const Pose& world_T_camera,
                        const std::string& source, double weight = 0.7, std::vector<std::string>* warnings = nullptr);

}  // namespace demoplan::perception
