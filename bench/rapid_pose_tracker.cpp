#include "bench/rapid_pose_tracker.h"

#include <opencv2/calib3d.hpp>
#include <opencv2/core/eigen.hpp>

namespace demoplan::bench {

using namespace demoplan::perception;

RapidPoseTracker::RapidPoseTracker(Kind kind, const std::vector<std::pair<std::string, RenderMesh>>& parts,
                                   TrackerInit init, double min_ratio)
    : kind_(kind), init_(std::move(init)), min_ratio_(min_ratio) {
  for (const auto& [id, mesh] : parts) {
    cv::Mat pts(static_cast<int>(mesh.vertices.size()), 3, CV_32F), tris(static_cast<int>(mesh.triangles.size()), 3, CV_32S);
    for (size_t i = 0; i < mesh.vertices.size(); ++i)
      for (int c = 0; c < 3; ++c) pts.at<float>(static_cast<int>(i), c) = mesh.vertices[i][c];
    for (size_t i = 0; i < mesh.triangles.size(); ++i)
      for (int c = 0; c < 3; ++c) tris.at<int>(static_cast<int>(i), c) = static_cast<int>(mesh.triangles[i][c]);
    trackers_.push_back(kind == Kind::Ols ? cv::Ptr<cv::rapid::Tracker>(cv::rapid::OLSTracker::create(pts, tris))
                                          : cv::Ptr<cv::rapid::Tracker>(cv::rapid::GOSTracker::create(pts, tris)));
    const Eigen::AlignedBox3f b = mesh.bounds();
    parts_.push_back({id, true, Eigen::AlignedBox3d(b.min().cast<double>(), b.max().cast<double>())});
  }
}

void RapidPoseTracker::start(const TrackingStart& start) {
  K_ = start.camera.camera_matrix();
  world_T_camera_ = *start.camera.world_T_camera;
  rvec_.clear(), tvec_.clear();
  tracks_ = PoseTracks();
  tracks_.fps = start.fps;
  for (size_t k = 0; k < parts_.size(); ++k) {
    tracks_.object_ids.push_back(parts_[k].id);
    tracks_.planning.push_back(true);
    const Pose T = world_T_camera_.inverse() * init_.find(parts_[k].id)->world_T_object;
    cv::Mat R, r, t;
    cv::eigen2cv(Eigen::Matrix3d(T.linear()), R);
    cv::Rodrigues(R, r);
    cv::eigen2cv(Eigen::Vector3d(T.translation()), t);
    rvec_.push_back(r), tvec_.push_back(t);
    trackers_[k]->clearState();
  }
  tracks_.resize(std::max(start.frames, 0));
}

std::vector<PoseObservation> RapidPoseTracker::track(int frame, const cv::Mat& image) {
  if (frame >= tracks_.frames) tracks_.resize(frame + 1);
  std::vector<PoseObservation> seen;
  for (size_t k = 0; k < parts_.size(); ++k) {
    cv::Mat r = rvec_[k].clone(), t = tvec_[k].clone();
    float ratio = 0.f;
    try {
      ratio = trackers_[k]->compute(image, 200, 20, K_, r, t);
    } catch (const cv::Exception&) {
      ratio = 0.f;  // the part's outline left the picture
    }
    if (ratio < min_ratio_ || !cv::checkRange(r) || !cv::checkRange(t)) continue;
    rvec_[k] = r, tvec_[k] = t;
    cv::Mat R;
    cv::Rodrigues(r, R);
    Eigen::Matrix3d Re;
    Eigen::Vector3d te;
    cv::cv2eigen(R, Re);
    cv::cv2eigen(t, te);
    Pose T = Pose::Identity();
    T.linear() = Re, T.translation() = te;
    PoseSample& s = tracks_.samples[k][frame];
    s.valid = true;
    s.pose = world_T_camera_ * T;
    s.confidence = ratio;
    seen.push_back({static_cast<int>(k), s});
  }
  return seen;
}

PoseTracks RapidPoseTracker::finish() { return tracks_; }

}  // namespace demoplan::bench
