#pragma once
// The whole extraction: video + camera + a pose tracker (+ optional BOP pose estimates and hand
// contacts) -> per-frame part poses -> grasp/release events -> Demonstration. The tracker is
// the caller's choice (tracking/pose_tracker.h); the camera's pose comes from the camera file
// or from its board, whatever the tracker.
#include <atomic>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "core/demo/demonstration.h"
#include "core/demo/settle_demonstration.h"
#include "core/scene/scene.h"
#include "perception/camera/camera_model.h"
#include "perception/events/contact_detector.h"
#include "perception/events/track_segmentation.h"
#include "perception/events/hand_fusion.h"
#include "perception/markers/marker_detector.h"
#include "perception/tracking/carrier_ride.h"
#include "perception/tracking/pose_track.h"
#include "perception/tracking/pose_tracker.h"

namespace demoplan::perception {

struct ExtractionOptions {
  ContactDetectorOptions contacts;
  // Which event detector reads the tracks: thresholds (detect_contacts, tuned on marker tracks)
  // or segments (segment_tracks, made for real detectors' noisier tracks).
  enum class Events { Thresholds, Segments } events = Events::Thresholds;
  TrackSegmentationOptions segmentation;
  HandFusionOptions hands;
  std::string bop_csv;     // optional BOP results file
  std::string hands_json;  // optional hand-contact detections
  std::string camera_source = "camera";  // names the camera file in messages
  bool board_extrinsics = false;  // estimate the camera pose from the board even if the file gives one
  int board_frames = 10;          // frames (with the board seen) averaged for the camera pose
  MarkerDetectorOptions board_detector;  // finds the board's markers
  double bop_weight = 0.7;  // confidence of a BOP estimate: its score times this
  // The scene the video shows (its furniture's supports, the parts' contact faces): when given,
  // every part resting near a support at an event is put onto it along the camera's line of
  // sight (a monocular estimate's depth is its weakest coordinate: the model tracker's rest
  // poses were 6-40 mm off, nearly all of it along the line of sight), within `settle`'s reach.
  std::shared_ptr<const Scene> scene;
  // Within 11 degrees and 5 cm in height: farther than the planner's settle, as a monocular
  // estimate of a part at rest is tilted by up to 7 degrees (tunnel_0 behind the occluder).
  SettleOptions settle{SnapOptions{.max_tilt = 0.2, .max_distance = 0.05, .gap = 0.001, .max_outside = 0.0, .viewpoint = {}}};
  // With the scene: a carrier's ride (a tray carried with parts on it) fitted to where its riders
  // show after it; the riders rest where it took them (carrier_rides.h). waiter_0 without markers:
  // the parts on the tray after its ride 27-35 mm off, 5-9 mm with it.
  bool fit_rides = true;
  CarrierRideOptions ride;
  std::function<void(int done, int total)> progress;
  const std::atomic<bool>* cancel = nullptr;
};

struct ExtractionResult {
  Demonstration demonstration;
  PoseTracks raw, smoothed;
  ContactAnalysis contacts;
  Pose world_T_camera = Pose::Identity();
  std::string extrinsics_source;  // "file" or "board (N frames)"
  std::string tracker;            // the tracker's name()
  int frames = 0;
  double seconds = 0.0;           // wall time of the whole extraction
  double frames_per_second = 0.0;
  std::vector<std::string> warnings;
  bool cancelled = false;  // then only `frames` and the timing are meaningful
};

// `tracker` is started, fed every frame and finished here; `task` names the demonstration's
// task. Throws InputError for unreadable or inconsistent inputs (naming the file and the
// frame, line or field).
ExtractionResult extract_demonstration(const std::string& video, const Camera& camera, PoseTracker& tracker,
                                       const std::string& task, const ExtractionOptions& options = {});

}  // namespace demoplan::perception
