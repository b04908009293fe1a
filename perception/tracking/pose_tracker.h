#pragma once
// The extension point between the video and the events: a pose tracker is handed every frame
// and gives back per-frame part poses (as OMPL's base::Planner is the abstract planner and its
// geometric planners implementations). The extraction pipeline (extract_demonstration) knows
// only this interface; what a tracker looks for is given to its constructor: the markers on
// the parts (MarkerPoseTracker), each part's mesh and its pose in the first frame (a
// model-based tracker), a file of imported poses (BOP CSV).
//
// Protocol: parts() at any time; start() once before the first frame; track() for every
// frame in order 0, 1, ...; finish() once after the last. start() again begins a new video.
#include <string>
#include <vector>

#include <Eigen/Geometry>
#include <opencv2/core.hpp>

#include "perception/camera/camera_model.h"
#include "perception/tracking/pose_track.h"

namespace demoplan::perception {

// A part the tracker follows; its index in parts() is its row in the tracks.
struct TrackedPart {
  std::string id;         // part id, as in the task
  bool planning = true;   // false: tracked but not planned for (a tray)
  // The part's extent in its own frame: where it shows in the image (the hand fusion looks
  // for hands touching it there).
  Eigen::AlignedBox3d extent{Eigen::Vector3d::Constant(-0.05), Eigen::Vector3d::Constant(0.05)};
};

// What a tracker learns before the first frame.
struct TrackingStart {
  Camera camera;     // intrinsics and world_T_camera (always set: from the file or the board)
  double fps = 30.0;
  int frames = 0;    // frames the video announces
};

class PoseTracker {
public:
  virtual ~PoseTracker() = default;

  // A short name for messages and files ("markers").
  virtual std::string name() const = 0;
  virtual const std::vector<TrackedPart>& parts() const = 0;
  // False when track() never looks at the image (imported poses, or no marker on any part):
  // the pipeline then passes empty images and spares the decoding.
  virtual bool needs_images() const { return true; }

  // Throws InputError when the tracker cannot work with this camera or video.
  virtual void start(const TrackingStart& start) = 0;
  // The parts seen in this frame, with world poses and confidences (0..1). A tracker may
  // revise them in finish() with what later frames showed (the marker tracker resolves a
  // flat marker's two-fold ambiguity from its neighbours).
  virtual std::vector<PoseObservation> track(int frame, const cv::Mat& image) = 0;
  // Tracks over every frame seen, one row per part in parts() order.
  virtual PoseTracks finish() = 0;
  // What the operator should know about the tracks (a start the frame does not bear out), one
  // line each naming the file and the part or frame; read after finish().
  virtual std::vector<std::string> warnings() const { return {}; }
};

}  // namespace demoplan::perception
