#pragma once
// How unlike a part's own look the image is where the part would show: its mesh drawn with its
// texture (or colour) at a pose, compared with the frame pixel by pixel. A box turned half
// round about its vertical has the same outline, and region tracking (which sees only the
// outline and the part's colours) cannot tell the two apart; its print can.
#include <opencv2/core.hpp>

#include "core/geometry/se3.h"
#include "perception/render/render_mesh.h"
#include "perception/tracking/region_pose.h"

namespace demoplan::perception {

// The mean absolute difference (0-255, per channel) between `image` and `mesh` drawn at
// `camera_T_part` (by the renderer, its light fixed in the world: `world_T_camera`), over the
// pixels where it shows (`occlusion`: what hides it; `part` its index there), both blurred by
// 5 px first (a pose a pixel off does not make the print's edges differ), the drawing first
// scaled per channel to the image's mean there (the video's light). Negative when fewer than
// `min_pixels` show.
double appearance_error(const cv::Mat& image, const PinholeIntrinsics& camera, const Pose& world_T_camera,
                        const RenderMesh& mesh, const Pose& camera_T_part, const OcclusionMap& occlusion, int part,
                        int min_pixels = 50);

// The same comparison in full: the mean difference (negative when nothing shows), over how many
// pixels, and of them how many differ by more than `outlier` on average over the channels (> 0:
// something not modelled, such as a hand, in front of the part there).
struct PrintDifference {
  double error = -1.0;
  int pixels = 0;
  int outliers = 0;
};
PrintDifference print_difference(const cv::Mat& image, const PinholeIntrinsics& camera, const Pose& world_T_camera,
                                 const RenderMesh& mesh, const Pose& camera_T_part, const OcclusionMap& occlusion,
                                 int part, double outlier = 0.0);

// A frame kept for a part's print to be fitted to later: the frame, what hid the part in it, the
// pose it was looked at, and the fraction of the pixels it showed in that differed (2: none kept).
struct PrintShot {
  int frame = -1;
  cv::Mat image;
  OcclusionMap map;
  Pose camera_T_part = Pose::Identity();
  double outliers = 2.0;
};

// Turns `camera_T_part` about the world's vertical through the part's `centre` (part frame) while
// its print differs less from `image` (appearance_error), steps halving from `turn` down to
// `min_turn` (rad). `error_before` and `error`: the print's difference at the start and at the fit
// (negative: too little of it shows).
struct PrintTurn {
  Pose camera_T_part = Pose::Identity();
  double error_before = -1.0, error = -1.0;
};
PrintTurn turn_to_print(const cv::Mat& image, const PinholeIntrinsics& camera, const Pose& world_T_camera,
                        const RenderMesh& mesh, const Pose& camera_T_part, const Eigen::Vector3d& centre,
                        const OcclusionMap& occlusion, int part, double turn = 0.07, double min_turn = 0.004);

}  // namespace demoplan::perception
