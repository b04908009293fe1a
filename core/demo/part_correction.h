#pragma once
// A part the operator placed again at a later frame of the video, after the part-model tracker
// lost it or followed it wrongly: the tracker takes it from there as from a start. Kept in the
// tracker start file (perception's tracker_init.h, "corrections") and in the project
// ("tracker_corrections", placed with the GUI's gizmo).
#include <functional>
#include <string>
#include <vector>

#include "core/geometry/se3.h"
#include "core/io/json_file.h"

namespace demoplan {

struct PartCorrection {
  std::string id;  // the part's id in the scene
  int frame = 0;   // video frame, after the tracker's start frame
  Pose world_T_object = Pose::Identity();  // metres, world frame
};

// The placements listed in `list` ({"id", "frame", "world_T_object"} each, the pose in the form
// `pose` reads), in their order. Throws InputError naming the entry's field for a part `known`
// refuses (`unknown` says where it is missing: "has no start in \"parts\""), a frame not after
// `start_frame`, and a part placed twice in one frame.
std::vector<PartCorrection> read_part_corrections(const JsonField& list, int start_frame,
                                                  const std::function<bool(const std::string&)>& known,
                                                  const std::string& unknown,
                                                  const std::function<Pose(const JsonField&)>& pose);

}  // namespace demoplan
