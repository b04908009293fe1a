#pragma once
// Whether two oriented boxes overlap: the separating axis test (the 3 face normals of each box
// and their 9 cross products). Exact for boxes; touching counts as overlapping.
#include <Eigen/Core>

#include "core/geometry/se3.h"

namespace demoplan {

// Boxes centred at their poses' origins, `half` their half sizes along their own axes.
bool boxes_overlap(const Pose& a, const Eigen::Vector3d& half_a, const Pose& b, const Eigen::Vector3d& half_b);

}  // namespace demoplan
