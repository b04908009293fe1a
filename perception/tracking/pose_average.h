#pragma once
// The plain mean of a few poses: chordal mean rotation (the rotation nearest to the mean
// matrix) and mean translation. For samples that may hold outliers, use core's
// robust_static_pose (core/demo/rest_pose.h) instead.
#include <vector>

#include "core/geometry/se3.h"
#include "core/scene/scene.h"

namespace demoplan::perception {

Eigen::Matrix3d mean_rotation(const std::vector<Eigen::Matrix3d>& rotations);
Pose mean_pose(const PoseList& poses);

}  // namespace demoplan::perception
