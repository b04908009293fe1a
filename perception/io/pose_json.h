#pragma once
// Poses in perception files: written as {"t":[x,y,z],"q":[qx,qy,qz,qw]} (metres, unit quaternion
// scalar last); read in that form or as a 4x4 row-major matrix.
#include "core/io/json_file.h"

namespace demoplan::perception {

Json pose_to_json(const Pose& pose);
// Throws InputError naming the field for a malformed pose, a zero quaternion or a
// non-orthonormal rotation.
Pose pose_from_json(const JsonField& field);

}  // namespace demoplan::perception
