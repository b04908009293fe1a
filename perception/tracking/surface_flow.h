#pragma once
// Where points on a part's surface went between two frames: corners of the last frame inside
// the part's rendered silhouette (where nothing nearer hides it), followed into this frame by
// pyramidal Lucas-Kanade optical flow. Each gives a point on the part (its frame) and where it is
// seen now: the texture's hold on the pose, which a silhouette alone lacks for turns of a
// near-symmetric part and for depth.
#include <vector>

#include <Eigen/Core>
#include <opencv2/core.hpp>

#include "core/geometry/se3.h"
#include "perception/tracking/region_pose.h"

namespace demoplan::perception {

struct SurfaceFlowOptions {
  int corners = 60;          // per part
  double min_distance = 6;   // px between corners
  int border = 3;            // px kept off the silhouette's edge (at the map's scale)
  int window = 15;           // px, Lucas-Kanade window
  int levels = 3;            // pyramid levels
  double max_error = 20.0;   // mean absolute grey difference of the window: beyond, dropped
};

// `last`: the parts rendered at their poses in the last frame (labels and depth); `camera_T_part`
// those poses; `follow[k]`: whether to follow part k. Images are 8-bit grey.
std::vector<std::vector<SurfacePoint>> follow_surface_points(const cv::Mat& last_gray, const cv::Mat& gray,
                                                             const OcclusionMap& last, const std::vector<Pose>& camera_T_part,
                                                             const std::vector<bool>& follow, const PinholeIntrinsics& camera,
                                                             const SurfaceFlowOptions& options = {});

}  // namespace demoplan::perception
