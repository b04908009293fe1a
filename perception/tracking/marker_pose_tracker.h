#pragma once
// The pose tracker for parts carrying ArUco markers: finds the markers in each frame
// (MarkerDetector) and turns them into part poses (MarkerTracker).
#include <optional>
#include <string>
#include <vector>

#include "perception/markers/marker_detector.h"
#include "perception/markers/marker_scene.h"
#include "perception/tracking/marker_tracker.h"
#include "perception/tracking/pose_tracker.h"

namespace demoplan::perception {

class MarkerPoseTracker final : public PoseTracker {
public:
  // Tracks the scene's objects, in its order; a part's extent is the box its markers span.
  explicit MarkerPoseTracker(MarkerScene scene, const MarkerDetectorOptions& detector = {},
                             const MarkerTrackerOptions& tracker = {});

  std::string name() const override { return "markers"; }
  const std::vector<TrackedPart>& parts() const override { return parts_; }
  bool needs_images() const override { return has_markers_; }
  void start(const TrackingStart& start) override;
  std::vector<PoseObservation> track(int frame, const cv::Mat& image) override;
  PoseTracks finish() override;

private:
  MarkerScene scene_;
  MarkerDetector detector_;
  MarkerTrackerOptions options_;
  std::vector<TrackedPart> parts_;
  bool has_markers_ = false;  // without any, no frame needs looking at
  std::optional<MarkerTracker> tracker_;  // from start() on
};

}  // namespace demoplan::perception
