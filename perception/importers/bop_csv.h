#pragma once
// 6D object pose estimates in the BOP challenge results format, as CosyPose and other BOP
// methods write them: a CSV file with the header
//   scene_id,im_id,obj_id,score,R,t,time
// and one line per estimate, R = 9 numbers separated by spaces (row-major 3x3 rotation,
// model to camera), t = 3 numbers separated by spaces (millimetres, model to camera), time =
// seconds spent on the image (-1 when unknown). demoplan reads im_id as the video frame index
// (0-based) and obj_id as the YCB-V model number (obj_id 2 = part "YCBV_02").
#include <string>
#include <vector>

#include "core/geometry/se3.h"

namespace demoplan::perception {

struct BopDetection {
  int scene_id = 0;
  int image_id = 0;   // video frame
  int object_id = 0;  // BOP model id
  double score = 1.0;
  Pose camera_T_object = Pose::Identity();  // metres
  double time = -1.0;
  int line = 0;  // 1-based line in the file, for messages
};

// Throws InputError(path, "line N", reason) for a malformed line (field count, numbers,
// a rotation that is not orthonormal within 1e-3, a negative frame).
std::vector<BopDetection> load_bop_csv(const std::string& path);
void save_bop_csv(const std::string& path, const std::vector<BopDetection>& detections);

// "YCBV_02" -> 2; -1 for a part that is not a YCB-V model.
int bop_object_id(const std::string& part_id);

}  // namespace demoplan::perception
