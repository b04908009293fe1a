#pragma once
// The model tracker's start from a 6D pose estimator's output instead of the operator's
// placement: a BOP results CSV (bop_csv.h) that a GPU method (CosyPose, FoundationPose, ...) wrote
// for the video's frames. The start frame is the first frame with an estimate of every part;
// each part starts at its best-scoring estimate there, turned into the world by the camera's pose.
#include <string>
#include <vector>

#include "core/geometry/se3.h"
#include "perception/importers/bop_csv.h"
#include "perception/tracking/tracker_init.h"

namespace demoplan::perception {

// `parts`: the ids of every part the tracker follows (each a BOP model: "YCBV_02" is obj_id 2).
// Throws InputError naming `source`: a part that is no BOP model, or no frame with every part.
TrackerInit tracker_init_from_bop(const std::vector<BopDetection>& detections, const std::vector<std::string>& parts,
                                  const Pose& world_T_camera, const std::string& source);

}  // namespace demoplan::perception
