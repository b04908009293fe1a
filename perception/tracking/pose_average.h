#pragma once
// Averages of a few poses: chordal mean rotation (the rotation nearest to the mean matrix) and
// mean or median translation; interpolation between two poses.
#include <vector>

#include "core/geometry/se3.h"
#include "core/scene/scene.h"

namespace demoplan::perception {

Eigen::Matrix3d mean_rotation(const std::vector<Eigen::Matrix3d>& rotations);
Pose mean_pose(const PoseList& poses);
// Median translation per axis, chordal mean rotation: for samples with a few outliers.
Pose median_pose(const PoseList& poses);
// Linear in translation, spherical in rotation; s in [0, 1].
Pose interpolate(const Pose& a, const Pose& b, double s);

}  // namespace demoplan::perception
