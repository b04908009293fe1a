#pragma once
// For comparison only (docs/benchmarks.md, "Model-based tracker"): OpenCV contrib's silhouette
// trackers (cv::rapid: OLSTracker, Seo et al. 2013; GOSTracker, Wang et al. 2015) behind our
// PoseTracker interface, one per part, from the same start poses as ModelPoseTracker. They know
// nothing of occlusion, rest or search: a part whose ratio of matched search lines drops below
// `min_ratio` keeps its last pose, reported invalid.
#include <memory>
#include <string>
#include <vector>

#include <opencv2/rapid.hpp>

#include "perception/render/render_mesh.h"
#include "perception/tracking/pose_tracker.h"
#include "perception/tracking/tracker_init.h"

namespace demoplan::bench {

class RapidPoseTracker final : public perception::PoseTracker {
public:
  enum class Kind { Ols, Gos };
  RapidPoseTracker(Kind kind, const std::vector<std::pair<std::string, perception::RenderMesh>>& parts,
                   perception::TrackerInit init, double min_ratio = 0.5);

  std::string name() const override { return kind_ == Kind::Ols ? "rapid-ols" : "rapid-gos"; }
  const std::vector<perception::TrackedPart>& parts() const override { return parts_; }
  void start(const perception::TrackingStart& start) override;
  std::vector<perception::PoseObservation> track(int frame, const cv::Mat& image) override;
  perception::PoseTracks finish() override;

private:
  Kind kind_;
  perception::TrackerInit init_;
  double min_ratio_;
  std::vector<perception::TrackedPart> parts_;
  std::vector<cv::Ptr<cv::rapid::Tracker>> trackers_;
  std::vector<cv::Mat> rvec_, tvec_;  // camera_T_part, CV_64F 3x1
  cv::Matx33d K_;
  Pose world_T_camera_ = Pose::Identity();
  perception::PoseTracks tracks_;
};

}  // namespace demoplan::bench
