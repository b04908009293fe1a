#pragma once
// Where to put the camera of a synthetic video: looking down at the parts' whole motion at a
// fixed elevation, from the azimuth where no furniture hides a resting part and the view is
// tightest (largest markers), with the focal length of a typical 1280x720 webcam.
#include <vector>

#include <Eigen/Geometry>

#include "perception/camera/camera_model.h"
#include "perception/markers/marker_scene.h"
#include "perception/synthetic/demo_script.h"

namespace demoplan::perception {

struct CameraPlacementOptions {
  cv::Size image_size{1280, 720};
  double fx = 1100.0;            // px (about 60 degrees horizontal field of view)
  std::vector<double> elevations{0.45, 0.6, 0.75, 0.9};  // rad above the horizontal, tried in turn
  double margin_px = 60.0;       // keep the motion this far inside the image border
  int azimuths = 24;
  std::vector<Eigen::Vector3d> also_in_view;  // world points kept in the image besides the motion
};

// Whether the segment from a to b (its last 5 cm excluded) crosses the box.
bool segment_hits_box(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::AlignedBox3d& box);

// How well the chosen view sees the parts at rest.
struct CameraPlacementReport {
  int blind_rests = 0;    // a part at one of its rests showing none of its markers
  int hidden_points = 0;  // of the rests' centres and pulled-in corners, behind furniture
};

// `obstacles`: world boxes of furniture that may hide parts (not the floor). `markers`: per part
// (optional), the markers on it; a view where a resting part shows none of them (facing the
// camera within 70 degrees and not hidden) is avoided above all.
Camera place_camera(const DemoScript& script, const std::vector<Eigen::AlignedBox3d>& obstacles,
                    const std::vector<std::vector<ObjectMarker>>& markers = {},
                    const CameraPlacementOptions& options = {}, CameraPlacementReport* report = nullptr);

}  // namespace demoplan::perception
