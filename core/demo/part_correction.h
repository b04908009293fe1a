#pragma once
// A part the operator placed again at a later frame of the video, after the part-model tracker
// lost it or followed it wrongly: the tracker takes it from there as from a start. Kept in the
// tracker start file (perception's tracker_init.h, "corrections") and in the project
// ("tracker_corrections", placed with the GUI's gizmo).
#include <string>

#include "core/geometry/se3.h"

namespace demoplan {

struct PartCorrection {
  std::string id;  // the part's id in the scene
  int frame = 0;   // video frame, after the tracker's start frame
  Pose world_T_object = Pose::Identity();  // metres, world frame
};

}  // namespace demoplan
