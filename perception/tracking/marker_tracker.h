#pragma once
// Part poses from the markers seen in each frame. Per part and frame: every visible marker
// gives the two square-marker solutions; the one that best explains all the part's visible
// corners is refined on all of them (several faces of a part act as a rigid board). When the
// visible markers all lie in one plane and the flipped solution explains them almost as well,
// the frame is ambiguous: finish() picks the solution closest in rotation to the nearest
// unambiguous frame of the same part, before or after it. (MarkerPoseTracker wraps it, with
// the marker detector, as a PoseTracker.)
#include <vector>

#include "perception/camera/camera_model.h"
#include "perception/markers/marker_detector.h"
#include "perception/markers/marker_scene.h"
#include "perception/tracking/pose_track.h"

namespace demoplan::perception {

struct MarkerTrackerOptions {
  double ambiguity_ratio = 3.0;   // flipped solution within this factor of the best's error: ambiguous
  double ambiguity_margin_px = 0.1;
  double inlier_px = 2.0;            // a marker farther off the part's pose is left out
  double max_reprojection_px = 3.0;  // worse: no sample
  int max_gap = 30;               // frames an ambiguous sample may look for its reference
  double corner_sigma_px = 0.15;  // corner noise assumed for the samples' expected precision
  // Markers seen nearly edge-on (quad area below this fraction of its longest side squared,
  // about 70 deg from frontal) are left out: their corners say little and are often off.
  double min_squareness = 0.35;
  // A marker whose edges could not be measured and whose shortest side is shorter than this
  // (px) is left out: its bits are barely resolved and its corners often off by pixels.
  double min_unrefined_side_px = 20.0;
};

class MarkerTracker {
public:
  // `camera` must have world_T_camera.
  MarkerTracker(const MarkerScene& scene, const Camera& camera, double fps, const MarkerTrackerOptions& options = {});

  // Returns the parts this frame shows, an ambiguous one with its best solution for now.
  std::vector<PoseObservation> add_frame(int frame, const std::vector<MarkerDetection>& markers);
  PoseTracks finish();

private:
  struct Alternative {
    Pose camera_T_object;
    double reprojection_px;
    double sigma_translation = 0.0, sigma_rotation = 0.0;
  };
  struct Observation {
    int frame = -1;
    std::vector<Alternative> alternatives;  // best first; two when ambiguous
    int markers = 0;
    std::uint64_t marker_set = 0;  // PoseSample::marker_set
    bool refined = false;  // every marker used had its edges measured
  };

  // The sample of an observation with one of its alternatives; `unresolved`: an ambiguous one
  // that no neighbour decided.
  PoseSample sample_of(const Observation& observation, size_t alternative, bool unresolved) const;

  MarkerScene scene_;
  Camera camera_;
  double fps_;
  MarkerTrackerOptions options_;
  int frames_ = 0;
  std::vector<std::vector<Observation>> observations_;  // [object]
};

}  // namespace demoplan::perception
