#include "perception/tracking/marker_pose_tracker.h"

#include <stdexcept>
#include <utility>

namespace demoplan::perception {

MarkerPoseTracker::MarkerPoseTracker(MarkerScene scene, const MarkerDetectorOptions& detector,
                                     const MarkerTrackerOptions& tracker)
    : scene_(std::move(scene)), detector_(scene_.dictionary, detector), options_(tracker) {
  for (const auto& o : scene_.objects) {
    parts_.push_back({o.id, o.planning, marker_extent(o)});
    has_markers_ = has_markers_ || !o.markers.empty();
  }
}

void MarkerPoseTracker::start(const TrackingStart& start) {
  tracker_.emplace(scene_, start.camera, start.fps, options_);
}

std::vector<PoseObservation> MarkerPoseTracker::track(int frame, const cv::Mat& image) {
  if (!tracker_) throw std::logic_error("MarkerPoseTracker::track before start");
  if (!has_markers_) return tracker_->add_frame(frame, {});
  return tracker_->add_frame(frame, detector_.detect(image));
}

PoseTracks MarkerPoseTracker::finish() {
  if (!tracker_) throw std::logic_error("MarkerPoseTracker::finish before start");
  return tracker_->finish();
}

}  // namespace demoplan::perception
