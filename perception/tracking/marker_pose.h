#pragma once
// Pose of one square marker from its four corners: OpenCV's square-marker solver
// (SOLVEPNP_IPPE_SQUARE) returns the two poses a planar square cannot tell apart from one
// view; both are kept, best first, for the tracker to choose over time.
#include <vector>

#include "core/geometry/se3.h"
#include "perception/camera/camera_model.h"
#include "perception/markers/marker_detector.h"

namespace demoplan::perception {

struct MarkerPoseCandidate {
  Pose camera_T_marker;
  double reprojection_px = 0.0;  // RMS over the four corners
};

// Corners of a marker of black side `size` in its frame, in the detector's order.
std::vector<cv::Point3d> marker_corner_points(double size);

// One or two candidates, smallest reprojection error first.
std::vector<MarkerPoseCandidate> marker_pose_candidates(const MarkerDetection& marker, double size, const Camera& camera);

}  // namespace demoplan::perception
