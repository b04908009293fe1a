#pragma once
// Turning noisy per-frame pose estimates of a resting object into one pose that rests exactly
// on its support, as the benchmark's placement test wants it.
#include <optional>
#include <vector>

#include "core/scene/scene.h"
#include "core/scene/support.h"

namespace demoplan {

// A robust average of pose samples of a still object: median translation; rotation averaged
// over the samples within `inlier_angle` of the medoid rotation (the sample closest to all).
Pose robust_static_pose(const PoseList& samples, double inlier_angle = 0.17);

struct SnapOptions {
  double max_tilt = 0.35;       // rad: face normal to support normal, beyond this no match
  double max_distance = 0.05;   // m: face centroid to support plane
  double gap = 0.001;           // m: where the face ends up above the support
  // m: how far outside the support the face centroid may project; such an object is moved
  // inside, 1 cm past the edge. 0: it must project inside.
  double max_outside = 0.0;
  // Where the pose was seen from (a camera's centre, world): the height is then set by moving
  // the object along the line of sight through its middle, not along the support's normal. A
  // monocular estimate's depth is its weakest coordinate; its place in the image is its best.
  // Lines of sight within 10 degrees of the support's plane fall back to the normal.
  std::optional<Eigen::Vector3d> viewpoint;
};

struct SnapResult {
  Pose pose;          // corrected pose, in the frame the support's vertices are given in
  int support = -1;   // index of the chosen support polygon
  int face = -1;      // index of the object's contact polygon that rests on it
  double tilt = 0.0;  // rad, rotation applied
  double shift = 0.0; // m, height change along the normal applied
  double slide = 0.0; // m, translation within the plane to bring it onto the support
};

// Finds the object face and support polygon that fit the pose best (smallest tilt, then
// distance) and moves the object onto it: rotated about its middle (the centroid of all its
// contact polygons) so the face is parallel to the support, then shifted along the normal (or
// the line of sight from `viewpoint`) to `gap` above it, and slid inside the polygon (max_outside). `supports` are in
// the same frame as `pose` (world for furniture, the link frame for a robot surface).
std::optional<SnapResult> snap_to_support(const std::vector<std::vector<Eigen::Vector3d>>& object_faces,
                                          const Pose& pose,
                                          const std::vector<std::vector<Eigen::Vector3d>>& supports,
                                          const SnapOptions& options = {});

}  // namespace demoplan
