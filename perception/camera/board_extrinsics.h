#pragma once
// The camera's pose in the world from an ArUco board lying at a known place (MarkerBoard).
#include <optional>
#include <vector>

#include "perception/camera/camera_model.h"
#include "perception/markers/marker_detector.h"

namespace demoplan::perception {

struct BoardPose {
  Pose world_T_camera;
  int markers = 0;
  double reprojection_px = 0.0;
};

// From the board markers among `detections` (at least `min_markers` of them); nullopt else.
std::optional<BoardPose> camera_pose_from_board(const MarkerBoard& board, const Camera& camera,
                                                const std::vector<MarkerDetection>& detections, int min_markers = 2);

}  // namespace demoplan::perception
