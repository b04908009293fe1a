#pragma once
// Where each part is in one frame of the video: what a model-based tracker starts from (the
// operator places the parts over that frame, or a pose estimator gives them).
//
// File "demoplan-tracker-init" version 1 (JSON):
//   {"format": "demoplan-tracker-init", "version": 1, "frame": 0,
//    "parts": [{"id": "YCBV_02", "world_T_object": {"t": [x, y, z], "q": [qx, qy, qz, qw]}}],
//    "corrections": [{"id": "YCBV_02", "frame": 75, "world_T_object": {...}}]}
// Poses in metres in the world frame of the camera file (the same as the scene's).
// `corrections` (optional): where the operator placed a part again later in the video, after
// the tracker lost it or followed it wrongly; the tracker takes it from there as from a start.
#include <string>
#include <vector>

#include "core/demo/part_correction.h"
#include "core/geometry/se3.h"

namespace demoplan::perception {

struct PartStart {
  std::string id;
  Pose world_T_object = Pose::Identity();
};

using demoplan::PartCorrection;  // a part placed again at a later frame (an operator's correction)

struct TrackerInit {
  int frame = 0;
  std::vector<PartStart> parts;
  std::vector<PartCorrection> corrections;  // in the file's order

  const PartStart* find(const std::string& id) const;
};

// Throws InputError naming the file and field: malformed poses, duplicate ids, a negative frame,
// a correction of a part without a start, at or before the start frame, or given twice.
TrackerInit load_tracker_init(const std::string& path);
void save_tracker_init(const std::string& path, const TrackerInit& init);

}  // namespace demoplan::perception
