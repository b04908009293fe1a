#pragma once
// Where a mesh's silhouette edge lies in a camera's image: what an operator compares with the
// video to see whether a part's pose fits (the video panel's start poses). Rendered with the
// software rasterizer over the part's own box in the image only, so one outline of a YCB-V part
// costs about a millisecond.
#include <vector>

#include <opencv2/core.hpp>

#include "core/geometry/se3.h"
#include "perception/camera/camera_model.h"
#include "perception/render/render_mesh.h"

namespace demoplan::perception {

// The silhouette's edge as polylines in image pixels (the camera's distortion applied); a closed
// edge repeats its first point at the end. Where the part leaves the image the edge is cut there
// (the image border is not the part's edge). Empty when nothing of the part shows, the part is
// behind the camera, or the camera has no pose.
std::vector<std::vector<cv::Point2f>> silhouette_outline(const RenderMesh& mesh, const Pose& world_T_mesh,
                                                         const Camera& camera);

}  // namespace demoplan::perception
