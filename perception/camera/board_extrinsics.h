#pragma once
// The camera's pose in the world from an ArUco board lying at a known place (MarkerBoard): in
// one frame, and over the first frames of a video that show it. Independent of how the parts
// are tracked: any pose tracker gets the camera pose found here.
#include <optional>
#include <string>
#include <vector>

#include "perception/camera/camera_model.h"
#include "perception/markers/marker_detector.h"
#include "perception/video/video_reader.h"

namespace demoplan::perception {

struct BoardPose {
  Pose world_T_camera;
  int markers = 0;
  double reprojection_px = 0.0;
};

// From the board markers among `detections` (at least `min_markers` of them); nullopt else.
std::optional<BoardPose> camera_pose_from_board(const MarkerBoard& board, const Camera& camera,
                                                const std::vector<MarkerDetection>& detections, int min_markers = 2);

struct VideoBoardPose {
  Pose world_T_camera;
  int frames = 0;  // frames averaged
};

// The robust average of the camera poses of the first `max_frames` frames that show at least
// 3 markers of the camera's board. Throws InputError naming `camera_source` when the camera
// has no board, and the video (field "board") when no frame shows it.
VideoBoardPose camera_pose_from_board_video(VideoReader& video, const Camera& camera, const std::string& camera_source,
                                            const MarkerDetectorOptions& detector = {}, int max_frames = 10);

}  // namespace demoplan::perception
