#pragma once
// Conversions between OpenCV's rotation vector + translation (rvec, tvec: what solvePnP and
// projectPoints take) and Pose.
#include <opencv2/core.hpp>

#include "core/geometry/se3.h"

namespace demoplan::perception {

Pose pose_from_rvec_tvec(const cv::Vec3d& rvec, const cv::Vec3d& tvec);
void rvec_tvec_from_pose(const Pose& pose, cv::Vec3d& rvec, cv::Vec3d& tvec);

}  // namespace demoplan::perception
