#include "perception/camera/opencv_pose.h"

#include <opencv2/calib3d.hpp>

namespace demoplan::perception {

Pose pose_from_rvec_tvec(const cv::Vec3d& rvec, const cv::Vec3d& tvec) {
  cv::Matx33d R;
  cv::Rodrigues(rvec, R);
  Pose T = Pose::Identity();
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) T.linear()(r, c) = R(r, c);
    T.translation()[r] = tvec[r];
  }
  return T;
}

void rvec_tvec_from_pose(const Pose& pose, cv::Vec3d& rvec, cv::Vec3d& tvec) {
  cv::Matx33d R;
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) R(r, c) = pose.linear()(r, c);
    tvec[r] = pose.translation()[r];
  }
  cv::Rodrigues(R, rvec);
}

}  // namespace demoplan::perception
