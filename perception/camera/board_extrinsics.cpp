#include "perception/camera/board_extrinsics.h"

#include <cmath>

#include <opencv2/calib3d.hpp>

#include "core/demo/rest_pose.h"
#include "core/error.h"
#include "perception/camera/opencv_pose.h"

namespace demoplan::perception {

std::optional<BoardPose> camera_pose_from_board(const MarkerBoard& board, const Camera& camera,
                                                const std::vector<MarkerDetection>& detections, int min_markers) {
  const auto grid = board.make();
  std::vector<cv::Point3d> object;
  std::vector<cv::Point2d> image;
  int used = 0;
  for (const auto& d : detections) {
    if (!board.owns(d.id)) continue;
    const auto& pts = grid->objPoints[d.id - board.first_id];
    for (int k = 0; k < 4; ++k) {
      object.emplace_back(pts[k].x, pts[k].y, pts[k].z);
      image.emplace_back(d.corners[k].x, d.corners[k].y);
    }
    ++used;
  }
  if (used < min_markers) return std::nullopt;
  cv::Vec3d rvec, tvec;
  // Planar points: IPPE gives the global optimum's neighbourhood, LM polishes it.
  if (!cv::solvePnP(object, image, camera.camera_matrix(), camera.distortion_coefficients(), rvec, tvec, false,
                    cv::SOLVEPNP_IPPE))
    return std::nullopt;
  cv::solvePnPRefineLM(object, image, camera.camera_matrix(), camera.distortion_coefficients(), rvec, tvec);
  std::vector<cv::Point2d> projected;
  cv::projectPoints(object, rvec, tvec, camera.camera_matrix(), camera.distortion_coefficients(), projected);
  double sum = 0;
  for (size_t i = 0; i < image.size(); ++i) sum += std::pow(cv::norm(projected[i] - image[i]), 2);
  BoardPose out;
  out.world_T_camera = board.world_T_board * pose_from_rvec_tvec(rvec, tvec).inverse();
  out.markers = used;
  out.reprojection_px = std::sqrt(sum / static_cast<double>(image.size()));
  return out;
}

VideoBoardPose camera_pose_from_board_video(VideoReader& video, const Camera& camera, const std::string& camera_source,
                                            const MarkerDetectorOptions& detector_options, int max_frames) {
  if (!camera.board)
    throw InputError(camera_source, "world_T_camera", "the camera file gives neither the camera's pose nor a board to find it");
  const MarkerDetector detector(camera.board->dictionary, detector_options);
  PoseList poses;
  for (int f = 0; f < video.frame_count() && static_cast<int>(poses.size()) < max_frames; ++f)
    if (const auto b = camera_pose_from_board(*camera.board, camera, detector.detect(video.frame(f)), 3))
      poses.push_back(b->world_T_camera);
  if (poses.empty())
    throw InputError(video.path(), "board", "the board of the camera file is not seen (3 markers or more) in any frame");
  return {robust_static_pose(poses), static_cast<int>(poses.size())};
}

}  // namespace demoplan::perception
