#include "perception/tracking/marker_tracker.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <opencv2/calib3d.hpp>
#include <opencv2/imgproc.hpp>

#include "perception/camera/opencv_pose.h"
#include "perception/tracking/marker_pose.h"

namespace demoplan::perception {

namespace {

double rotation_distance(const Pose& a, const Pose& b) {
  return Eigen::AngleAxisd(a.linear().transpose() * b.linear()).angle();
}

double rms_error(const std::vector<cv::Point3d>& object, const std::vector<cv::Point2d>& image, const Pose& T,
                 const Camera& camera) {
  cv::Vec3d rvec, tvec;
  rvec_tvec_from_pose(T, rvec, tvec);
  std::vector<cv::Point2d> projected;
  cv::projectPoints(object, rvec, tvec, camera.camera_matrix(), camera.distortion_coefficients(), projected);
  double sum = 0;
  for (size_t i = 0; i < image.size(); ++i) {
    const cv::Point2d d = projected[i] - image[i];
    sum += d.dot(d);
  }
  return std::sqrt(sum / static_cast<double>(image.size()));
}

Pose refine(const std::vector<cv::Point3d>& object, const std::vector<cv::Point2d>& image, const Pose& guess,
            const Camera& camera) {
  cv::Vec3d rvec, tvec;
  rvec_tvec_from_pose(guess, rvec, tvec);
  cv::solvePnPRefineLM(object, image, camera.camera_matrix(), camera.distortion_coefficients(), rvec, tvec);
  return pose_from_rvec_tvec(rvec, tvec);
}

// Standard deviations of a pose fitted to these points, for corner noise `sigma_px`: from the
// Jacobian of the projection (first-order covariance of the least-squares fit).
std::pair<double, double> pose_sigmas(const std::vector<cv::Point3d>& object, const Pose& T, const Camera& camera,
                                      double sigma_px) {
  cv::Vec3d rvec, tvec;
  rvec_tvec_from_pose(T, rvec, tvec);
  std::vector<cv::Point2d> projected;
  cv::Mat J;
  cv::projectPoints(object, rvec, tvec, camera.camera_matrix(), camera.distortion_coefficients(), projected, J);
  cv::Mat J6 = J.colRange(0, 6);
  cv::Mat cov;
  if (cv::invert(J6.t() * J6, cov, cv::DECOMP_SVD) == 0) return {1.0, 1.0};
  cov *= sigma_px * sigma_px;
  cv::Mat er, et;
  cv::eigen(cov(cv::Rect(0, 0, 3, 3)), er);
  cv::eigen(cov(cv::Rect(3, 3, 3, 3)), et);
  return {std::sqrt(std::max(0.0, et.at<double>(0))), std::sqrt(std::max(0.0, er.at<double>(0)))};
}

bool coplanar(const std::vector<const ObjectMarker*>& markers) {
  const Eigen::Vector3d n = markers.front()->object_T_marker.linear().col(2);
  const Eigen::Vector3d p = markers.front()->object_T_marker.translation();
  for (const auto* m : markers) {
    if (m->object_T_marker.linear().col(2).dot(n) < 0.999) return false;
    if (std::abs((m->object_T_marker.translation() - p).dot(n)) > 1e-3) return false;
  }
  return true;
}

}  // namespace

MarkerTracker::MarkerTracker(const MarkerScene& scene, const Camera& camera, double fps, const MarkerTrackerOptions& o)
    : scene_(scene), camera_(camera), fps_(fps), options_(o), observations_(scene.objects.size()) {
  if (!camera.world_T_camera) throw std::invalid_argument("MarkerTracker: the camera's pose in the world is unknown");
}

std::vector<PoseObservation> MarkerTracker::add_frame(int frame, const std::vector<MarkerDetection>& markers) {
  frames_ = std::max(frames_, frame + 1);
  std::vector<PoseObservation> seen_now;
  // Group the detections by part; where some of a part's markers had all their edges measured,
  // the others are partly hidden and left out.
  std::vector<std::vector<std::pair<const MarkerDetection*, const ObjectMarker*>>> seen(scene_.objects.size());
  for (const auto& d : markers) {
    int o, m;
    if (scene_.find_marker(d.id, o, m)) seen[o].push_back({&d, &scene_.objects[o].markers[m]});
  }
  for (auto& list : seen)
    if (std::any_of(list.begin(), list.end(), [](auto& x) { return x.first->edges_refined; }))
      list.erase(std::remove_if(list.begin(), list.end(), [](auto& x) { return !x.first->edges_refined; }), list.end());

  for (size_t o = 0; o < seen.size(); ++o) {
    if (seen[o].empty()) continue;
    const size_t n = seen[o].size();
    std::vector<std::vector<cv::Point3d>> object(n);
    std::vector<std::vector<cv::Point2d>> image(n);
    std::vector<Pose, Eigen::aligned_allocator<Pose>> candidates;
    for (size_t k = 0; k < n; ++k) {
      const auto& [det, mk] = seen[o][k];
      for (const auto& p : marker_corner_points(mk->size)) {
        const Eigen::Vector3d q = mk->object_T_marker * Eigen::Vector3d(p.x, p.y, p.z);
        object[k].emplace_back(q.x(), q.y(), q.z());
      }
      image[k].assign(det->corners.begin(), det->corners.end());
      const auto cands = marker_pose_candidates(*det, mk->size, camera_);
      if (cands.empty()) continue;
      // Seen nearly edge-on, a marker's corners say little and are often found off.
      const std::vector<cv::Point2f> quad(det->corners.begin(), det->corners.end());
      double longest = 0, shortest = 1e9;
      for (int c = 0; c < 4; ++c) {
        const double side = cv::norm(quad[(c + 1) % 4] - quad[c]);
        longest = std::max(longest, side);
        shortest = std::min(shortest, side);
      }
      if (std::abs(cv::contourArea(quad)) < options_.min_squareness * longest * longest ||
          (!det->edges_refined && shortest < options_.min_unrefined_side_px)) {
        image[k].clear();  // not used below
        continue;
      }
      for (const auto& c : cands) candidates.push_back(c.camera_T_marker * mk->object_T_marker.inverse());
    }
    if (candidates.empty()) continue;
    // Markers a pose explains (each within max_reprojection_px) and their joint error.
    auto inliers_of = [&](const Pose& T, std::vector<size_t>& in, double& total) {
      in.clear();
      total = 0;
      for (size_t k = 0; k < n; ++k) {
        if (image[k].empty()) continue;  // left out
        const double e = rms_error(object[k], image[k], T, camera_);
        if (e <= options_.inlier_px) in.push_back(k), total += e;
      }
    };
    auto gather = [&](const std::vector<size_t>& in, std::vector<cv::Point3d>& obj, std::vector<cv::Point2d>& img) {
      obj.clear();
      img.clear();
      for (size_t k : in) {
        obj.insert(obj.end(), object[k].begin(), object[k].end());
        img.insert(img.end(), image[k].begin(), image[k].end());
      }
    };
    // Consensus: the candidate that explains the most markers, then the smallest error.
    struct Scored {
      size_t count;
      double total;
      size_t index;
    };
    std::vector<Scored> scored;
    for (size_t i = 0; i < candidates.size(); ++i) {
      std::vector<size_t> in;
      double total;
      inliers_of(candidates[i], in, total);
      scored.push_back({in.size(), total, i});
    }
    std::sort(scored.begin(), scored.end(), [](const Scored& a, const Scored& b) {
      return a.count != b.count ? a.count > b.count : a.total < b.total;
    });
    if (scored.front().count == 0) continue;
    std::vector<size_t> in;
    double total;
    inliers_of(candidates[scored.front().index], in, total);
    std::vector<cv::Point3d> obj;
    std::vector<cv::Point2d> img;
    gather(in, obj, img);
    Pose best = refine(obj, img, candidates[scored.front().index], camera_);
    // Once more with the markers the refined pose explains.
    std::vector<size_t> again;
    inliers_of(best, again, total);
    if (!again.empty() && again != in) {
      in = again;
      gather(in, obj, img);
      best = refine(obj, img, best, camera_);
    }
    const double best_err = rms_error(obj, img, best, camera_);
    if (best_err > options_.max_reprojection_px) continue;
    Observation obs;
    obs.frame = frame;
    obs.markers = static_cast<int>(in.size());
    for (size_t k : in) obs.marker_set |= std::uint64_t{1} << (seen[o][k].second->id % 64);
    obs.refined = std::all_of(in.begin(), in.end(), [&](size_t k) { return seen[o][k].first->edges_refined; });
    const auto [sigma_t, sigma_r] = pose_sigmas(obj, best, camera_, options_.corner_sigma_px);
    obs.alternatives.push_back({best, best_err, sigma_t, sigma_r});
    std::vector<const ObjectMarker*> used;
    for (size_t k : in) used.push_back(seen[o][k].second);
    if (coplanar(used)) {
      // The flipped solution of the same markers: ambiguous when it explains them almost as well.
      for (const auto& sc : scored) {
        if (rotation_distance(candidates[sc.index], best) < 0.17) continue;
        const Pose flipped = refine(obj, img, candidates[sc.index], camera_);
        const double flipped_err = rms_error(obj, img, flipped, camera_);
        if (rotation_distance(flipped, best) > 0.17 &&
            flipped_err < std::max(options_.ambiguity_ratio * best_err, best_err + options_.ambiguity_margin_px))
          obs.alternatives.push_back({flipped, flipped_err, sigma_t, sigma_r});
        break;
      }
    }
    const bool ambiguous = obs.alternatives.size() > 1;
    seen_now.push_back({static_cast<int>(o), sample_of(obs, 0, ambiguous)});
    observations_[o].push_back(std::move(obs));
  }
  return seen_now;
}

PoseSample MarkerTracker::sample_of(const Observation& obs, size_t alternative, bool unresolved) const {
  const bool ambiguous = obs.alternatives.size() > 1;
  const Alternative& a = obs.alternatives[alternative];
  PoseSample s;
  s.valid = true;
  s.pose = *camera_.world_T_camera * a.camera_T_object;
  s.markers = obs.markers;
  s.marker_set = obs.marker_set;
  s.reprojection_px = a.reprojection_px;
  s.sigma_translation = a.sigma_translation;
  s.sigma_rotation = a.sigma_rotation;
  s.ambiguous = ambiguous;
  // Confidence that the pose is right (not how precise it is: sigma_* say that).
  s.confidence = std::exp(-std::pow(a.reprojection_px / 1.5, 2));
  if (!obs.refined) s.confidence *= 0.8;  // corners not checked against the marker's edges
  if (ambiguous) s.confidence *= unresolved ? 0.65 : 0.85;
  return s;
}

PoseTracks MarkerTracker::finish() {
  PoseTracks tracks;
  tracks.fps = fps_;
  for (const auto& o : scene_.objects) {
    tracks.object_ids.push_back(o.id);
    tracks.planning.push_back(o.planning);
  }
  tracks.resize(frames_);
  for (size_t o = 0; o < observations_.size(); ++o) {
    const auto& obs = observations_[o];
    const int n = static_cast<int>(obs.size());
    std::vector<int> choice(n, -1);  // alternative chosen, -1: undecided
    for (int i = 0; i < n; ++i)
      if (obs[i].alternatives.size() == 1) choice[i] = 0;
    // Ambiguous frames follow the nearest decided frame within max_gap, looking both ways;
    // decided frames propagate outwards one step at a time, so chains of ambiguous frames work.
    auto pick = [&](int i, int ref) {
      const Pose& r = obs[ref].alternatives[choice[ref]].camera_T_object;
      double best = 1e9;
      for (size_t a = 0; a < obs[i].alternatives.size(); ++a) {
        const double d = rotation_distance(obs[i].alternatives[a].camera_T_object, r);
        if (d < best) best = d, choice[i] = static_cast<int>(a);
      }
    };
    for (int i = 1; i < n; ++i)
      if (choice[i] < 0 && choice[i - 1] >= 0 && obs[i].frame - obs[i - 1].frame <= options_.max_gap) pick(i, i - 1);
    for (int i = n - 2; i >= 0; --i)
      if (choice[i] < 0 && choice[i + 1] >= 0 && obs[i + 1].frame - obs[i].frame <= options_.max_gap) pick(i, i + 1);
    for (int i = 0; i < n; ++i) {
      const bool unresolved = choice[i] < 0;
      tracks.samples[o][obs[i].frame] = sample_of(obs[i], unresolved ? 0 : static_cast<size_t>(choice[i]), unresolved);
    }
  }
  return tracks;
}

}  // namespace demoplan::perception
