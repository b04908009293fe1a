#include "perception/tracking/marker_pose.h"

#include <algorithm>

#include <opencv2/calib3d.hpp>

#include "perception/camera/opencv_pose.h"

namespace demoplan::perception {

std::vector<cv::Point3d> marker_corner_points(double size) {
  const double h = size / 2;
  return {{-h, h, 0}, {h, h, 0}, {h, -h, 0}, {-h, -h, 0}};
}

std::vector<MarkerPoseCandidate> marker_pose_candidates(const MarkerDetection& marker, double size, const Camera& camera) {
  const std::vector<cv::Point3d> object = marker_corner_points(size);
  std::vector<cv::Point2d> image(marker.corners.begin(), marker.corners.end());
  std::vector<cv::Mat> rvecs, tvecs;
  cv::Mat errors;
  cv::solvePnPGeneric(object, image, camera.camera_matrix(), camera.distortion_coefficients(), rvecs, tvecs, false,
                      cv::SOLVEPNP_IPPE_SQUARE, cv::noArray(), cv::noArray(), errors);
  if (!errors.empty()) errors.convertTo(errors, CV_64F);
  std::vector<MarkerPoseCandidate> out;
  for (size_t i = 0; i < rvecs.size(); ++i) {
    MarkerPoseCandidate c;
    c.camera_T_marker = pose_from_rvec_tvec(cv::Vec3d(rvecs[i]), cv::Vec3d(tvecs[i]));
    c.reprojection_px = errors.empty() ? 0.0 : errors.at<double>(static_cast<int>(i));
    if (c.camera_T_marker.translation().z() > 0) out.push_back(c);
  }
  std::sort(out.begin(), out.end(), [](auto& a, auto& b) { return a.reprojection_px < b.reprojection_px; });
  return out;
}

}  // namespace demoplan::perception
