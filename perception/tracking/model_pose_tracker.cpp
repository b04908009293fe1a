#include "perception/tracking/model_pose_tracker.h"

#include <algorithm>
#include <cstdio>
#include <cmath>
#include <deque>
#include <future>
#include <optional>
#include <stdexcept>
#include <thread>
#include <tuple>
#include <utility>

#include <opencv2/calib3d.hpp>
#include <opencv2/imgproc.hpp>

#include "core/error.h"
#include "core/geometry/polygon_2d.h"
#include "core/parallel_for.h"
#include "perception/render/part_meshes.h"
#include "perception/render/rasterizer.h"
#include "perception/tracking/appearance_error.h"
#include "perception/tracking/color_blobs.h"
#include "perception/tracking/carrier_top.h"
#include "perception/tracking/contour_model_file.h"
#include "perception/tracking/light_correction.h"
#include "perception/tracking/placement_witness.h"
#include "perception/tracking/rest_hold.h"
#include "perception/tracking/surface_flow.h"

namespace demoplan::perception {

namespace {

// Two poses of one rest: within 3 mm and a degree (held rests repeat it exactly).
bool same_rest(const Pose& a, const Pose& b) {
  return (a.translation() - b.translation()).norm() <= 0.003 &&
         Eigen::AngleAxisd(a.linear().transpose() * b.linear()).angle() <= 0.0175;
}
// Fewer pixels of a part's print than this showing say too little of its turn.
constexpr int kRestTurnPixels = 200;

// A measurement's confidence: full from a contrast of 0.5 with half the lines on an edge.
double confidence_of(const RegionFrameResult& r) {
  const double used = static_cast<double>(r.used_lines) / r.lines;
  return std::clamp(r.contrast / 0.5, 0.0, 1.0) * std::min(1.0, used / 0.5);
}

}  // namespace

struct ModelPoseTracker::State {
  PinholeIntrinsics intrinsics;
  cv::Size image_size;
  Pose world_T_camera = Pose::Identity();
  cv::Mat undistort_x, undistort_y;  // empty without distortion
  std::vector<Pose> camera_T_part;
  std::vector<ColorHistograms> colors;
  std::vector<double> reference_contrast;  // running mean of each part's accepted contrast
  std::vector<std::optional<Pose>> previous;  // the pose a frame before, while seen in both
  std::vector<std::vector<Eigen::Vector2d>> centres;  // image of the centre, the last three frames seen
  std::vector<bool> seen_last;                        // seen in the last frame
  std::vector<RenderMesh> silhouettes;  // untextured meshes for the occlusion map
  cv::Mat furniture_depth;              // the furniture at the occlusion map's scale; empty: none
  cv::Mat furniture_labels;             // OcclusionMap::kFurniture where it shows, the same scale
  cv::Mat last_gray;                    // the last frame, for the surface points' flow
  LightReference light;                 // the start frame's light
  std::vector<SupportLevel> supports;   // the furniture's upward faces, where a lost part may rest
  std::vector<Eigen::Matrix3d> rest_rotation;  // each part's world orientation at its last rest
  std::vector<std::optional<Pose>> rest_find;  // found at rest in the last frame (rest_search), to confirm
  std::vector<int> unseen;                     // frames each part has not been seen in, in a row
  std::vector<int> moved_for;                  // frames each part was seen moving in a row, last it was seen
  std::vector<int> measured_at;                // the last frame each part's pose was measured in (-1: none)
  std::vector<RestHold> holds;                 // each part's, while it is held at its rest (rest_hold.h)
  std::vector<std::optional<Pose>> rest_world;  // each part's pose (world) when last measured at rest
  std::vector<int> left_rest;                   // the frame that rest broke in (-1: not since)
  std::vector<int> rest_began;                  // the first frame of each part's current rest
  // A rest that stood on nothing and was found nowhere it could stand: the part is taken as
  // lost there, and looked for only where it could stand until seen (rest_recheck_unplaced).
  std::vector<bool> doubted;
  std::vector<int> unplaced_checks;  // rechecks in a row that found the current rest so
  // Each part's ride (ride_prediction.h), while it may have ridden: the riders, and its own rest
  // (world) their motion is applied to.
  struct Riding {
    Ride ride;
    Pose rest;
  };
  std::vector<std::optional<Riding>> rides;
  std::deque<std::pair<int, cv::Mat>> recent;  // the last frames (follow_back, date_rest_back)
  std::vector<bool> was_resting;               // each part rested in the last frame
  PoseTracks tracks;
  // Per part, the clearest frame of its current rest so far (the fewest pixels unlike its
  // print), to turn that rest by (ModelTrackerOptions::rest_turn).
  std::vector<PrintShot> rest_shots;
  std::vector<PlacementWitness> witnesses;  // each part's last placement, against its track
  bool started = false;  // the init frame has been seen
};

ModelPoseTracker::ModelPoseTracker(std::vector<ModelPart> parts, TrackerInit init, std::string init_source,
                                   std::vector<FurnitureMesh> furniture, const ModelTrackerOptions& options)
    : models_(std::move(parts)), furniture_(std::move(furniture)), init_(std::move(init)),
      init_source_(std::move(init_source)), options_(options) {
  for (const auto& m : models_) {
    if (!init_.find(m.id)) throw InputError(init_source_, "parts", "no starting pose for part '" + m.id + "'");
    if (m.mesh.triangles.empty()) throw InputError(m.id, "mesh", "the part has no mesh to track");
    const Eigen::AlignedBox3f b = m.mesh.bounds();
    parts_.push_back({m.id, m.planning, Eigen::AlignedBox3d(b.min().cast<double>(), b.max().cast<double>())});
  }
  for (size_t i = 0; i < init_.corrections.size(); ++i)
    if (part_index(init_.corrections[i].id) < 0)
      throw InputError(init_source_, "corrections[" + std::to_string(i) + "].id",
                       "part '" + init_.corrections[i].id + "' is not tracked (not in the scene)");
}

int ModelPoseTracker::part_index(const std::string& id) const {
  for (size_t k = 0; k < models_.size(); ++k)
    if (models_[k].id == id) return static_cast<int>(k);
  return -1;
}

ModelPoseTracker::~ModelPoseTracker() = default;

void ModelPoseTracker::start(const TrackingStart& start) {
  if (contours_.empty()) {
    // The silhouettes of every part from every direction: once (and kept on disk when a cache
    // folder is given), the parts in parallel.
    std::vector<std::future<std::unique_ptr<ContourModel>>> jobs;
    for (const auto& m : models_)
      jobs.push_back(std::async(std::launch::async, [&m, this] {
        return std::make_unique<ContourModel>(cached_contour_model(m.mesh, options_.contour, options_.contour_cache));
      }));
    for (auto& j : jobs) contours_.push_back(j.get());
  }
  state_ = std::make_unique<State>();
  warnings_.clear();
  State& s = *state_;
  const Camera& c = start.camera;
  if (!c.world_T_camera) throw std::logic_error("ModelPoseTracker::start without the camera pose");
  s.world_T_camera = *c.world_T_camera;
  s.image_size = c.image_size;
  s.intrinsics = {c.fx, c.fy, c.cx, c.cy};
  bool distorted = false;
  for (double d : c.distortion) distorted = distorted || d != 0.0;
  if (distorted)
    cv::initUndistortRectifyMap(c.camera_matrix(), c.distortion_coefficients(), cv::Mat(), c.camera_matrix(), c.image_size,
                                CV_16SC2, s.undistort_x, s.undistort_y);
  s.camera_T_part.assign(models_.size(), Pose::Identity());
  s.colors.assign(models_.size(), ColorHistograms());
  s.reference_contrast.assign(models_.size(), 0.0);
  s.previous.assign(models_.size(), std::nullopt);
  s.centres.assign(models_.size(), {});
  s.seen_last.assign(models_.size(), true);
  for (const auto& m : models_) s.silhouettes.push_back(m.mesh.geometry());
  s.rest_find.assign(models_.size(), std::nullopt);
  s.unseen.assign(models_.size(), 0);
  s.moved_for.assign(models_.size(), 0);
  s.rest_shots.assign(models_.size(), {});
  s.witnesses.assign(models_.size(), {});
  s.measured_at.assign(models_.size(), -1);
  s.holds.assign(models_.size(), RestHold());
  s.rest_world.assign(models_.size(), std::nullopt);
  s.left_rest.assign(models_.size(), -1);
  s.rest_began.assign(models_.size(), 0);
  s.doubted.assign(models_.size(), false);
  s.unplaced_checks.assign(models_.size(), 0);
  s.was_resting.assign(models_.size(), true);
  s.rides.assign(models_.size(), std::nullopt);
  if (options_.rest_search) s.supports = support_levels(furniture_);
  if (!furniture_.empty()) {
    Rasterizer r = occlusion_rasterizer();
    for (const auto& f : furniture_)
      r.draw_depth(f.mesh.geometry(), s.world_T_camera.inverse() * f.world_T_mesh);
    s.furniture_depth = r.depth().clone();
    s.furniture_labels = cv::Mat(s.furniture_depth.size(), CV_8U, cv::Scalar(0));
    s.furniture_labels.setTo(OcclusionMap::kFurniture, s.furniture_depth < 1e9f);
  }
  // A start (or a correction) that puts a part behind the camera or its centre beside the
  // picture is a wrong placement, not a part to look for.
  auto check_placement = [&](size_t k, const Pose& world_T_object, const std::string& field) {
    const std::string& id = models_[k].id;
    const Pose camera_T_part = s.world_T_camera.inverse() * world_T_object;
    if ((camera_T_part * contours_[k]->centre()).z() < 0.05)
      throw InputError(init_source_, field, "puts part '" + id + "' behind the camera");
    const Eigen::Vector2d at = centre_in_image(k, camera_T_part) + Eigen::Vector2d(s.intrinsics.cx, s.intrinsics.cy);
    if (at.x() < 0 || at.y() < 0 || at.x() >= s.image_size.width || at.y() >= s.image_size.height)
      throw InputError(init_source_, field,
                       "puts part '" + id + "' outside the " + std::to_string(s.image_size.width) + "x" +
                           std::to_string(s.image_size.height) + " image (its centre at pixel " +
                           std::to_string(static_cast<int>(at.x())) + ", " + std::to_string(static_cast<int>(at.y())) + ")");
  };
  for (size_t k = 0; k < models_.size(); ++k) {
    const PartStart& p = *init_.find(models_[k].id);
    check_placement(k, p.world_T_object, "parts[" + std::to_string(&p - init_.parts.data()) + "].world_T_object");
  }
  for (size_t i = 0; i < init_.corrections.size(); ++i)
    check_placement(static_cast<size_t>(part_index(init_.corrections[i].id)), init_.corrections[i].world_T_object,
                    "corrections[" + std::to_string(i) + "].world_T_object");
  s.tracks.fps = start.fps;
  for (const auto& p : parts_) {
    s.tracks.object_ids.push_back(p.id);
    s.tracks.planning.push_back(p.planning);
  }
  s.tracks.resize(std::max(start.frames, 0));
}

Rasterizer ModelPoseTracker::occlusion_rasterizer() const {
  const State& s = *state_;
  const double k = OcclusionMap().scale;
  const cv::Size size(static_cast<int>(s.image_size.width * k) + 1, static_cast<int>(s.image_size.height * k) + 1);
  Rasterizer r(size, s.intrinsics.fx * k, s.intrinsics.fy * k, (s.intrinsics.cx + 0.5) * k - 0.5,
               (s.intrinsics.cy + 0.5) * k - 0.5, Pose::Identity());
  if (s.furniture_depth.empty()) r.clear({0, 0, 0}, {0, 0, 0});
  else r.restore(cv::Mat(), s.furniture_depth);
  return r;
}

void ModelPoseTracker::on_search_threads(size_t count, size_t chunk, const std::function<void(size_t)>& work) const {
  const int threads = options_.search_threads > 0 ? options_.search_threads
                                                  : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  chunk = std::max<size_t>(chunk, 1);
  parallel_for((count + chunk - 1) / chunk, threads, [&](size_t c) {
    for (size_t i = c * chunk; i < std::min(count, (c + 1) * chunk); ++i) work(i);
  });
}

OcclusionMap ModelPoseTracker::occlusion_map(int skip) const {
  const State& s = *state_;
  OcclusionMap map;
  Rasterizer r = occlusion_rasterizer();
  map.labels = s.furniture_depth.empty() ? cv::Mat(cv::Mat::zeros(r.depth().size(), CV_8U)) : s.furniture_labels.clone();
  for (size_t p = 0; p < models_.size(); ++p) {
    if (static_cast<int>(p) == skip) continue;
    // A part not planned for (a tray) lies under what it carries and hides none of it: the
    // parts' depth, centimetres off at a few metres, would sink them into it.
    if (!parts_[p].planning) continue;
    r.draw_depth(s.silhouettes[p], s.camera_T_part[p], &map.labels, static_cast<uchar>(p + 1));
  }
  map.depth = r.depth();  // the rasterizer's own, drawn into no more
  return map;
}

std::vector<PoseObservation> ModelPoseTracker::track(int frame, const cv::Mat& input) {
  if (!state_) throw std::logic_error("ModelPoseTracker::track before start");
  State& s = *state_;
  if (frame < init_.frame) return {};
  if (frame >= s.tracks.frames) s.tracks.resize(frame + 1);
  if (input.empty()) return {};
  cv::Mat image = input;
  if (!s.undistort_x.empty()) cv::remap(input, image, s.undistort_x, s.undistort_y, cv::INTER_LINEAR);
  // The colour models were learnt in the start frame's light (light_correction.h).
  if (!s.started) {
    s.light = light_reference(image);
  } else if (const cv::Scalar gain = light_gain(s.light, image, options_.light_tolerance); gain != cv::Scalar(1, 1, 1)) {
    cv::Mat corrected;
    cv::multiply(image, gain, corrected);
    image = corrected;
  }
  if (!s.started) {
    // The starting poses, and what the parts and their surroundings look like there.
    for (size_t k = 0; k < models_.size(); ++k)
      s.camera_T_part[k] = s.world_T_camera.inverse() * init_.find(models_[k].id)->world_T_object;
    {
      // GrabCut (settle_start) seeds its colour models by k-means from OpenCV's global random
      // generator: started from its initial state here, a start settles the same in every
      // extraction, the first of a process (the CLI) or a later one (the GUI, bench_extraction).
      cv::RNG& rng = cv::theRNG();
      const cv::RNG before = rng;
      rng = cv::RNG();
      for (size_t k = 0; k < models_.size(); ++k) settle_start(image, k);
      rng = before;
    }
    const OcclusionMap map = occlusion_map();
    for (size_t k = 0; k < models_.size(); ++k)
      learn_colors(image, s.intrinsics, *contours_[k], s.camera_T_part[k], map, static_cast<int>(k), s.colors[k],
                   options_.region);
    // Starts the frame does not bear out (start_cover_difference).
    for (size_t k = 0; k < models_.size(); ++k) {
      const PrintDifference d = print_difference(image, s.intrinsics, s.world_T_camera, models_[k].mesh,
                                                 s.camera_T_part[k], map, static_cast<int>(k), options_.start_cover_difference);
      if (d.pixels == 0 || d.outliers <= options_.start_covered_fraction * d.pixels) continue;
      const int percent = static_cast<int>(std::lround(100.0 * d.outliers / d.pixels));
      warnings_.push_back(init_source_ + ": part '" + models_[k].id + "', frame " + std::to_string(frame) + ": " +
                          std::to_string(percent) +
                          " % of what shows of it does not look like its mesh there (a hand in front of it? its "
                          "start off?): its track may start off, check its first frames");
    }
    // Parts rest where a demonstration starts: each holds its depth from the first frame on.
    for (size_t k = 0; k < models_.size(); ++k) s.centres[k].assign(3, centre_in_image(k, s.camera_T_part[k]));
    for (size_t k = 0; k < models_.size(); ++k) s.rest_rotation.push_back(s.world_T_camera.linear() * s.camera_T_part[k].linear());
    for (size_t k = 0; k < models_.size(); ++k) s.rest_world[k] = s.world_T_camera * s.camera_T_part[k];
    for (size_t k = 0; k < models_.size(); ++k) s.witnesses[k].place(frame, s.camera_T_part[k]);
    for (size_t k = 0; k < models_.size(); ++k)
      s.reference_contrast[k] = track_region(image, s.intrinsics, *contours_[k], s.colors[k], s.camera_T_part[k], map,
                                             static_cast<int>(k), options_.region).contrast;
    s.started = true;
  }
  const std::vector<size_t> corrected = apply_corrections(frame, image);
  const OcclusionMap map = occlusion_map();
  cv::Mat gray;
  cv::cvtColor(image, gray, cv::COLOR_BGR2GRAY);
  const auto points = follow_surface_points(s.last_gray, gray, map, s.camera_T_part, s.seen_last, s.intrinsics, options_.flow);
  s.last_gray = gray;
  // At rest: the image of the part's centre barely moved in the last three frames seen.
  std::vector<bool> resting(models_.size()), moving(models_.size());
  for (size_t k = 0; k < models_.size(); ++k) {
    resting[k] = s.centres[k].size() >= 3;
    for (size_t i = 1; resting[k] && i < s.centres[k].size(); ++i)
      resting[k] = (s.centres[k][i] - s.centres[k].front()).norm() < options_.rest_px;
    moving[k] = s.seen_last[k] && !resting[k];
  }
  if (options_.ride_prediction) watch_rides(frame, resting);
  // Lost a few frames ago (lost_mover_frames) in a carry (seen moving in three frames in a row,
  // not one estimate's jump): still passing in front of what it overlapped, as a moving part.
  std::vector<bool> lost_moving(models_.size());
  for (size_t k = 0; k < models_.size(); ++k) {
    if (s.seen_last[k]) s.moved_for[k] = moving[k] ? s.moved_for[k] + 1 : 0;
    lost_moving[k] = !s.seen_last[k] && !resting[k] && s.unseen[k] <= options_.lost_mover_frames && s.moved_for[k] >= 3;
  }
  std::vector<PoseObservation> seen;
  std::vector<bool> learn(models_.size(), false), learn_part(models_.size(), false);
  // Nearest first: a part a hand takes in this frame counts as moving for the parts behind it
  // in the same frame, before its (and the hand's) pull on their lines drags them along. A part
  // that may have ridden comes last, once its riders are where they are in this frame.
  std::vector<size_t> order(models_.size());
  for (size_t k = 0; k < order.size(); ++k) order[k] = k;
  std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) {
    if (s.rides[a].has_value() != s.rides[b].has_value()) return !s.rides[a].has_value();
    return (s.camera_T_part[a] * contours_[a]->centre()).z() < (s.camera_T_part[b] * contours_[b]->centre()).z();
  });
  for (const size_t k : order) {
    const int part = static_cast<int>(k);
    // Held at its rest while another part moves (rest_hold.h).
    RestHold& hold = s.holds[k];
    bool others_moving = false;
    for (size_t j = 0; j < models_.size(); ++j) others_moving = others_moving || (j != k && moving[j]);
    auto movers_at_rest = [&] { return hold.movers_at_rest(s.seen_last, s.centres, options_.rest_px); };
    const bool may_hold = options_.hold_resting &&
                          ((others_moving && (hold.on || (resting[k] && s.measured_at[k] == frame - 1))) ||
                           (hold.on && !movers_at_rest()));
    // Each part's place in the world: where it rested before this frame's move (its pose a frame
    // before, or the last one kept), or where it is now.
    auto places = [&](bool before) {
      std::vector<Eigen::Vector3d> p(models_.size());
      for (size_t j = 0; j < p.size(); ++j)
        p[j] = (s.world_T_camera * (before && s.previous[j] ? *s.previous[j] : s.camera_T_part[j])).translation();
      return p;
    };
    auto hold_frame = [&] { hold.hold(frame, k, moving, places(true)); };
    auto movers_rode = [&] { return hold.movers_rode(places(false), options_.hold_ride_min, options_.hold_ride_tolerance); };
    auto end_hold = [&](bool borne_out, bool unmeasured) {
      if (!hold.on) return;
      hold.on = false;
      if (!borne_out) return;
      // Not measured at its rest through the hold, though nothing modelled covered it there:
      // its colours did not fit what showed (they may have been learnt from a hand in front of
      // it), and what showed is taken for them.
      if (unmeasured && options_.hold_relearn && hold.colors.initialised() && hold.contrast > 0) {
        s.colors[k] = hold.colors;
        s.reference_contrast[k] = hold.contrast;
      }
      for (const int f : hold.frames) {
        PoseSample& held = s.tracks.samples[k][f];
        held.valid = true;
        held.pose = s.world_T_camera * s.camera_T_part[k];
        held.confidence = options_.held_confidence;
      }
    };
    const double bar = std::max(options_.lost_contrast, options_.relative_contrast * s.reference_contrast[k]);
    auto is_seen = [&](const RegionFrameResult& x) { return seen_in(x, bar); };
    // While the parts it rested with ride away, it goes as they go (ride_prediction.h). Not
    // measured since the last frame, it is looked for there before it is held at (or looked for
    // around) the rest it left.
    std::optional<Pose> ride_start;
    if (s.rides[k])
      if (const std::optional<Pose> M = s.rides[k]->ride.motion(ride_parts(frame), ride_rules()))
        ride_start = s.world_T_camera.inverse() * *M * s.rides[k]->rest;
    // Where the ride took it is a prediction from other parts, not a guess among many places as
    // the search's: seen there as a tracked frame is, on half its lines as a find.
    auto found_riding = [&](const RegionFrameResult& x) {
      return is_seen(x) && x.used_lines >= options_.search_used_fraction * x.lines;
    };
    // Found by the search (elsewhere than where it was tracked from): on clearer evidence still.
    auto found_elsewhere = [&](const RegionFrameResult& x) {
      return x.contrast >= options_.search_contrast * s.reference_contrast[k] && found_riding(x);
    };
    std::optional<RegionFrameResult> riding;
    if (ride_start && s.measured_at[k] < frame - 1)
      if (RegionFrameResult x = track_region(image, s.intrinsics, *contours_[k], s.colors[k], *ride_start, map, part,
                                             options_.region);
          found_riding(x))
        riding = x;
    // Found riding: it moved, it does not rest where it was.
    if (riding) resting[k] = false;
    // A resting part that a moving one passes in front of stays where it is, unmeasured: what
    // is left of its silhouette is too little to tell a move from the occluder's pull.
    if (resting[k] && passed_in_front(k, moving, lost_moving)) {
      if (may_hold) hold_frame();
      continue;
    }
    // A part seen in the last two frames goes on across the view as it moved between them (a
    // carry); not in depth, which a silhouette gives too weakly to extrapolate.
    Pose start = s.camera_T_part[k];
    if (s.previous[k]) {
      const Eigen::Vector3d now = s.camera_T_part[k].translation(), step = now - s.previous[k]->translation();
      const Eigen::Vector3d ray = now.normalized();
      start.translation() += options_.prediction * (step - step.dot(ray) * ray);
    }
    if (ride_start && !resting[k]) start = *ride_start;
    // At rest a part keeps its depth. Not seen well enough (an occluder over it, out of the
    // picture, faster than the lines reach): look around its last pose. The bar is relative to
    // how the part has stood out so far, as parts differ from their surroundings more or less.
    RegionFrameResult r = riding ? *riding
                                 : track_region(image, s.intrinsics, *contours_[k], s.colors[k], start, map, part,
                                                options_.region, resting[k], points[k]);
    const bool mostly_hidden = resting[k] && r.hidden_lines > options_.rest_hidden_fraction * r.lines;
    // Lost at rest (not in a carry) and tracked on from there to elsewhere: that is a find, and
    // is taken on a find's evidence; a frame's pull from the stale pose is not (the stale pose
    // marks no motion to follow). Refused, it counts as not seen there, its lines as measured.
    if (!riding && s.unseen[k] > 0 && s.moved_for[k] < 3 && is_seen(r) && !found_elsewhere(r)) {
      const Eigen::Vector3d c = contours_[k]->centre();
      if ((r.camera_T_part * c - s.camera_T_part[k] * c).norm() > options_.stale_jump_radii * contours_[k]->radius())
        r.contrast = -1.0;
    }
    // Its last pose is no place it can be: not tracked from there.
    if (s.doubted[k] && !riding) r.contrast = -1.0;
    if (!is_seen(r) || mostly_hidden) {
      if (may_hold) {
        // Not looked for elsewhere while held: the part moving, or the hand carrying it, may
        // show colours it learnt (waiter_0: the arm in front of it in the start frame).
        hold_frame();
        // What shows at the rest while nothing modelled covers it, for its colours if the hold
        // is borne out unmeasured.
        if (r.hidden_lines == 0 && options_.hold_relearn) {
          learn_colors(image, s.intrinsics, *contours_[k], s.camera_T_part[k], map, part, hold.colors, options_.region);
          hold.contrast = contour_contrast(image, s.intrinsics, *contours_[k], hold.colors, s.camera_T_part[k]);
        }
        continue;
      }
      // The movers at rest again (else it would be held on): borne out unless they rode.
      if (hold.on) end_hold(movers_at_rest() && !movers_rode(), true);
    } else if (hold.on) {
      // Measured: still at its rest (within what a resting part's moves are held to), or not.
      end_hold(within_rest_hold(k, r.camera_T_part), false);
    }
    auto beyond_radius = [&](const Pose& T) {
      return (centre_in_image(k, T) - centre_in_image(k, s.camera_T_part[k])).norm() > radius_in_image(k, s.camera_T_part[k]);
    };
    // Placed by the operator in this frame: not looked for elsewhere.
    const bool placed = std::find(corrected.begin(), corrected.end(), k) != corrected.end();
    if (!is_seen(r) && !placed && !s.doubted[k]) {
      // Not farther than its radius from a rest it was seen at in the last frame: a part taken
      // from rest has not got that far yet, and what the search finds there is what passed in
      // front of it (waiter_0: the sugar box carried past the cracker box, taken for it 30 cm off).
      // Seen in the last frame and found within its radius with nearly all its lines on an
      // edge, it is taken as a tracked frame is: a part just lifted stands out less against
      // what is behind it now than the bar for a find elsewhere asks (waiter_0's sugar box).
      auto found_near = [&](const RegionFrameResult& x) {
        return s.seen_last[k] && is_seen(x) && x.used_lines >= options_.near_used_fraction * x.lines &&
               !beyond_radius(x.camera_T_part);
      };
      if (const RegionFrameResult found_again = search(image, part, map);
          (found_elsewhere(found_again) && !(resting[k] && s.seen_last[k] && beyond_radius(found_again.camera_T_part))) ||
          found_near(found_again))
        r = found_again;
    }
    // Still not found: perhaps put down where it could rest; taken once found at the same place
    // in two frames in a row.
    bool found_resting = false;
    // (Every `rest_search_every` frames while it stays lost, and in the frame after a find:
    // a part lost for long costs less.)
    const bool rest_search_now = s.rest_find[k] || s.unseen[k] % std::max(options_.rest_search_every, 1) == 0;
    if (!is_seen(r) && !placed && options_.rest_search && !s.supports.empty() && rest_search_now) {
      bool where_colours_show = false;
      const std::optional<RegionFrameResult> found = rest_search(image, part, &where_colours_show);
      if (found && s.rest_find[k]) {
        const Eigen::Vector3d moved = found->camera_T_part * contours_[k]->centre() - *s.rest_find[k] * contours_[k]->centre();
        if (moved.norm() < options_.rest_confirm_mm * 1e-3) {
          r = *found;
          found_resting = true;
          // Found far from where it was lost, on its colours: the operator checks the carry.
          if (where_colours_show) {
            const double radii = (centre_in_image(k, r.camera_T_part) - centre_in_image(k, s.camera_T_part[k])).norm() /
                                 radius_in_image(k, s.camera_T_part[k]);
            char away[32];
            std::snprintf(away, sizeof away, "%.1f", radii);
            warnings_.push_back("part '" + models_[k].id + "', frame " + std::to_string(frame) + ": lost since frame " +
                                std::to_string(frame - s.unseen[k]) + ", found again where its colours show, " + away +
                                " of its radii from where it was last seen, standing on the furniture: check its carry");
          }
        }
      }
      s.rest_find[k] = found ? std::optional<Pose>(found->camera_T_part) : std::nullopt;
    } else {
      // Seen where it is: a find at the same place in the next frame is confirmed by it.
      s.rest_find[k] = is_seen(r) ? std::optional<Pose>(r.camera_T_part) : std::nullopt;
    }
    const bool seen_now = is_seen(r) || found_resting;
    if (seen_now) s.doubted[k] = false;
    const bool seen_before = s.seen_last[k];
    s.seen_last[k] = seen_now;
    s.unseen[k] = seen_now ? 0 : s.unseen[k] + 1;
    if (!seen_now) {
      // Keeps its last pose, and whether it rested there: not being seen is no move.
      s.previous[k].reset();
      continue;
    }
    if (resting[k] && !found_resting && r.hidden_lines > options_.rest_hidden_fraction * r.lines) {
      // Mostly hidden by other parts or the furniture: what shows of a resting part is too
      // little to move it by; it stays, unmeasured.
      continue;
    }
    if (resting[k]) {
      // A resting part stays put for moves within the measurement's own scatter (the image of
      // its centre within rest_hold_px, its turn within rest_hold_deg): only a real move breaks
      // the rest, and partly hidden parts do not creep.
      if (within_rest_hold(k, r.camera_T_part)) r.camera_T_part = s.camera_T_part[k];
    }
    s.centres[k].push_back(centre_in_image(k, r.camera_T_part));
    if (s.centres[k].size() > 3) s.centres[k].erase(s.centres[k].begin());
    // Found at rest (at the same place in two frames): it rests there from now on, its depth and
    // place held as a start frame's are, not drifting while three frames' measurements settle.
    // So does a part found where a ride that is over (its riders at rest) took it.
    const bool ride_over = riding && std::all_of(s.rides[k]->ride.riders().begin(), s.rides[k]->ride.riders().end(),
                                                 [&](size_t j) { return resting[j] && s.seen_last[j]; });
    // So does a part placed again by the operator, as measured there.
    if (found_resting || ride_over || placed) s.centres[k].assign(3, s.centres[k].back());
    // Motion is carried on only between frames both seen: a part found again after a gap did
    // not move from its stale pose in one frame.
    if (seen_before && !riding)
      s.previous[k] = s.camera_T_part[k];
    else
      s.previous[k].reset();
    // Its rest broke (not in the start frame, where the parts rest, nor where the operator placed
    // it again: a first measurement's correction is no move), or it stays there; found riding,
    // it moves.
    if (resting[k] && frame > init_.frame && !placed && !r.camera_T_part.isApprox(s.camera_T_part[k])) {
      moving[k] = true;
      s.left_rest[k] = frame;
    } else if (resting[k] || found_resting || ride_over) {
      s.rest_world[k] = s.world_T_camera * r.camera_T_part;
      s.left_rest[k] = -1;
    }
    if (riding && !ride_over) moving[k] = true;
    // Seen at rest, it rides no more.
    if ((!riding && (resting[k] || found_resting)) || ride_over) s.rides[k].reset();
    s.camera_T_part[k] = r.camera_T_part;
    // Not from a find at rest: if it were wrong, the colours learnt there would hold it there.
    learn[k] = !found_resting && r.contrast >= options_.learn_contrast * s.reference_contrast[k];
    learn_part[k] = resting[k];
    if (resting[k]) s.rest_rotation[k] = s.world_T_camera.linear() * r.camera_T_part.linear();  // how it stands
    s.reference_contrast[k] += options_.reference_rate * (r.contrast - s.reference_contrast[k]);
    PoseSample& sample = s.tracks.samples[k][frame];
    sample.valid = true;
    sample.pose = s.world_T_camera * r.camera_T_part;
    sample.confidence = confidence_of(r);
    s.measured_at[k] = frame;
    seen.push_back({part, sample});
    // Found at rest: the frames before that show it there are at its rest (the hand withdrawing
    // after setting it down), and from the earliest of them it is followed back into its carry
    // (tracked free there from the rest, a frame's slide in depth would carry on into the rest).
    if (found_resting) follow_back(k, date_rest_back(k, frame, bar, 1), bar);
    // Come to rest (three frames still): the frames before may show it there already.
    if (resting[k] && !s.was_resting[k]) {
      s.rest_began[k] = options_.date_rests_back ? date_rest_back(k, frame, bar) : frame - 2;
      s.unplaced_checks[k] = 0;
    }
  }
  // A part placed again is where the operator put it in this frame, measured or not; the frames
  // before, since it was lost, may show it there already.
  for (const size_t k : corrected) {
    PoseSample& sample = s.tracks.samples[k][frame];
    if (!sample.valid) {
      sample.valid = true;
      sample.pose = s.world_T_camera * s.camera_T_part[k];
      sample.confidence = 1.0;
      seen.push_back({static_cast<int>(k), sample});
    }
    // At the rest first (a part put down some frames before, the hand still near it), then,
    // from the earliest frame that shows it there, back into its carry.
    const double bar = std::max(options_.lost_contrast, options_.relative_contrast * s.reference_contrast[k]);
    follow_back(k, date_rest_back(k, frame, bar, 1), bar);
    ride_back(k, frame);
  }
  // The last frames, kept a while: where a part comes to rest shows how it got there (while a
  // part is missed: follow_back; while one comes to rest: date_rest_back).
  s.was_resting = resting;
  const bool all_seen = std::all_of(s.seen_last.begin(), s.seen_last.end(), [](bool b) { return b; });
  if ((all_seen && !options_.date_rests_back) || options_.follow_back_frames <= 0) {
    s.recent.clear();
  } else {
    s.recent.emplace_back(frame, image.clone());
    if (static_cast<int>(s.recent.size()) > options_.follow_back_frames) s.recent.pop_front();
  }
  if (options_.rest_recheck && !s.supports.empty()) recheck_rests(frame, image, resting);
  if (options_.rest_turn) watch_rest_turns(frame, image, map, resting);
  if (options_.witness_placements) watch_placements(frame, image);
  const OcclusionMap after = occlusion_map();
  for (size_t k = 0; k < models_.size(); ++k)
    if (learn[k])
      learn_colors(image, s.intrinsics, *contours_[k], s.camera_T_part[k], after, static_cast<int>(k), s.colors[k],
                   options_.region, learn_part[k]);
  return seen;
}

std::vector<size_t> ModelPoseTracker::apply_corrections(int frame, const cv::Mat& image) {
  State& s = *state_;
  std::vector<size_t> corrected;
  for (const PartCorrection& c : init_.corrections) {
    if (c.frame != frame) continue;
    const auto k = static_cast<size_t>(part_index(c.id));
    s.camera_T_part[k] = s.world_T_camera.inverse() * c.world_T_object;
    corrected.push_back(k);
  }
  if (corrected.empty()) return corrected;
  // Placed by hand, as a start is: a few millimetres to centimetres off, moved to where the frame
  // shows it the same way (GrabCut's random generator from its initial state, as at the start).
  {
    cv::RNG& rng = cv::theRNG();
    const cv::RNG before = rng;
    rng = cv::RNG();
    for (const size_t k : corrected) settle_start(image, k);
    rng = before;
  }
  for (const size_t k : corrected) {
    const Pose world_T_object = s.world_T_camera * s.camera_T_part[k];
    // The last placement judged by the frames so far; this one by those from here.
    if (options_.witness_placements) {
      close_witness(k);
      s.witnesses[k].place(frame, s.camera_T_part[k]);
    }
    // At rest where it was put, as at the start: nothing of its last motion, rest or ride goes on.
    s.centres[k].assign(3, centre_in_image(k, s.camera_T_part[k]));
    s.previous[k].reset();
    s.seen_last[k] = true;
    s.was_resting[k] = true;
    s.unseen[k] = 0;
    s.moved_for[k] = 0;
    s.rest_find[k].reset();
    s.holds[k] = RestHold();
    s.rides[k].reset();
    s.rest_rotation[k] = world_T_object.linear();
    s.rest_world[k] = world_T_object;
    s.left_rest[k] = -1;
  }
  // Its colours learnt there too (what the tracker knew of it may be why it was lost), and how
  // well it stands out there as its bar from now on.
  const OcclusionMap map = occlusion_map();
  for (const size_t k : corrected) {
    const int part = static_cast<int>(k);
    learn_colors(image, s.intrinsics, *contours_[k], s.camera_T_part[k], map, part, s.colors[k], options_.region);
    s.reference_contrast[k] = track_region(image, s.intrinsics, *contours_[k], s.colors[k], s.camera_T_part[k], map, part,
                                           options_.region, true).contrast;
    s.measured_at[k] = frame - 1;
  }
  return corrected;
}

void ModelPoseTracker::follow_back(size_t k, int frame, double bar) {
  State& s = *state_;
  const OcclusionMap map = occlusion_map(static_cast<int>(k));
  Pose T = s.camera_T_part[k];
  for (auto it = s.recent.rbegin(); it != s.recent.rend(); ++it) {
    const int f = it->first;
    if (f >= frame) continue;
    PoseSample& sample = s.tracks.samples[k][f];
    if (sample.valid) break;  // back where it was seen
    // Free in depth: it was moving.
    const RegionFrameResult r =
        track_region(it->second, s.intrinsics, *contours_[k], s.colors[k], T, map, static_cast<int>(k), options_.region);
    if (!seen_in(r, bar)) break;
    T = r.camera_T_part;
    sample.valid = true;
    sample.pose = s.world_T_camera * T;
    sample.confidence = confidence_of(r);
  }
}

int ModelPoseTracker::date_rest_back(size_t k, int frame, double bar, int seen_for) {
  State& s = *state_;
  int earliest = frame - seen_for + 1;
  // Its rest is seen over the last `seen_for` frames (its image still there): reported at it,
  // not at their measurements' own depths, which scatter by millimetres.
  for (int f = std::max(earliest, 0); f < frame; ++f)
    if (PoseSample& sample = s.tracks.samples[k][f]; sample.valid) sample.pose = s.world_T_camera * s.camera_T_part[k];
  // The ones before are asked, latest first.
  const OcclusionMap map = occlusion_map();
  for (auto it = s.recent.rbegin(); it != s.recent.rend(); ++it) {
    const int f = it->first;
    if (f > frame - seen_for) continue;
    if (f < frame - options_.date_rests_back_frames - seen_for + 1) break;
    // At the rest's depth, from the rest pose: it stays there (within the rest hold) if it was there.
    const RegionFrameResult r = track_region(it->second, s.intrinsics, *contours_[k], s.colors[k], s.camera_T_part[k], map,
                                             static_cast<int>(k), options_.region, true);
    PoseSample& sample = s.tracks.samples[k][f];
    if (!seen_in(r, bar)) break;
    // Tracked from the rest it stays there; or the hand withdrawing over it pulls the outline
    // off, and the rest still shows the part at least as well as the estimate reported then
    // (which the hand dragged: waiter_0's cracker box laid down at 57, reported there from 60).
    auto rest_explains = [&] {
      if (!options_.date_rests_back_by_contrast || !sample.valid) return false;
      const double at_rest = contour_contrast(it->second, s.intrinsics, *contours_[k], s.colors[k], s.camera_T_part[k]);
      return at_rest >= options_.lost_contrast &&
             at_rest >= contour_contrast(it->second, s.intrinsics, *contours_[k], s.colors[k], s.world_T_camera.inverse() * sample.pose);
    };
    if (!within_rest_hold(k, r.camera_T_part) && !rest_explains()) break;
    sample.valid = true;
    sample.pose = s.world_T_camera * s.camera_T_part[k];
    sample.confidence = confidence_of(r);
    earliest = f;
  }
  return earliest;
}

void ModelPoseTracker::settle_start(const cv::Mat& image, size_t k) {
  State& s = *state_;
  const int part = static_cast<int>(k);
  // What the part looks like, from the start frame alone: colours learnt at a start some
  // centimetres off are half the part's and half its surroundings', and would hold the pose
  // where it is. A GrabCut segmentation around the start (its silhouette probably the part,
  // the rest of a box a radius larger probably not, the box's border surely not) separates the
  // part from what lies around it by colour and coherence.
  Rasterizer r(s.image_size, s.intrinsics.fx, s.intrinsics.fy, s.intrinsics.cx, s.intrinsics.cy, Pose::Identity());
  r.clear({0, 0, 0}, {0, 0, 0});
  r.draw_depth(s.silhouettes[k], s.camera_T_part[k]);
  const cv::Mat alone = r.depth().clone();
  // What else is in front: the other parts and the furniture. A part mostly hidden at its start
  // keeps it (too little of it shows to move it by); the others' pixels are surely not it.
  for (size_t j = 0; j < models_.size(); ++j)
    if (j != k) r.draw_depth(s.silhouettes[j], s.camera_T_part[j]);
  for (const auto& f : furniture_) r.draw_depth(f.mesh.geometry(), s.world_T_camera.inverse() * f.world_T_mesh);
  const cv::Mat silhouette = alone < 1e9f, hidden = r.depth() < alone, others = (r.depth() < 1e9f) & ~silhouette;
  const int area = cv::countNonZero(silhouette);
  if (area == 0 || cv::countNonZero(silhouette & ~hidden) < options_.settle_visible_fraction * area) return;
  const cv::Rect inside = cv::boundingRect(silhouette);
  const int margin = static_cast<int>(std::ceil(radius_in_image(k, s.camera_T_part[k])));
  const cv::Rect roi = cv::Rect(inside.x - margin, inside.y - margin, inside.width + 2 * margin, inside.height + 2 * margin) &
                       cv::Rect(cv::Point(0, 0), s.image_size);
  cv::Mat mask(roi.size(), CV_8U, cv::Scalar(cv::GC_PR_BGD));
  mask.setTo(cv::GC_PR_FGD, silhouette(roi) & ~hidden(roi));
  mask.setTo(cv::GC_BGD, hidden(roi) | others(roi));
  cv::rectangle(mask, cv::Rect(cv::Point(0, 0), roi.size()), cv::Scalar(cv::GC_BGD), 3);
  cv::Mat background_model, foreground_model;
  // A large part (a tray across half the view, tunnel_0's part near the camera) is segmented at
  // a smaller scale: GrabCut's cost grows with the pixels (0.39 s for 250,000), its colour models
  // do not need them all.
  constexpr double kGrabCutPixels = 120000;
  if (roi.area() <= kGrabCutPixels) {
    cv::grabCut(image(roi), mask, cv::Rect(), background_model, foreground_model, options_.settle_grabcut_iterations,
                cv::GC_INIT_WITH_MASK);
  } else {
    const double scale = std::sqrt(kGrabCutPixels / roi.area());
    cv::Mat small_image, small_mask;
    cv::resize(image(roi), small_image, cv::Size(), scale, scale, cv::INTER_AREA);
    cv::resize(mask, small_mask, small_image.size(), 0, 0, cv::INTER_NEAREST);
    cv::grabCut(small_image, small_mask, cv::Rect(), background_model, foreground_model,
                options_.settle_grabcut_iterations, cv::GC_INIT_WITH_MASK);
    cv::resize(small_mask, mask, mask.size(), 0, 0, cv::INTER_NEAREST);
  }
  ColorHistograms colors;
  for (int y = 0; y < roi.height; ++y)
    for (int x = 0; x < roi.width; ++x) {
      const cv::Vec3b& bgr = image.at<cv::Vec3b>(roi.y + y, roi.x + x);
      const auto label = mask.at<std::uint8_t>(y, x);
      if (label == cv::GC_FGD || label == cv::GC_PR_FGD)
        colors.add_foreground(bgr);
      else
        colors.add_background(bgr);
    }
  colors.update();
  // The start moved to where those colours put the part: across the view first (at the start's
  // depth), then in depth too; each move kept only when the part then stands out clearly better
  // (a start that is right stays as it is: the silhouette's size in particular is a weak cue,
  // and a small bias of the segmentation would shift the depth by centimetres).
  const OcclusionMap map = occlusion_map();
  // Judged by how well the part stands out where it would be with colours learnt there, as the
  // tracker will learn them: the segmentation proposes, it does not judge (parts with printed
  // patterns or markers segment poorly).
  auto contrast = [&](const Pose& T) {
    ColorHistograms there;
    learn_colors(image, s.intrinsics, *contours_[k], T, map, part, there, options_.region);
    return contour_contrast(image, s.intrinsics, *contours_[k], there, T);
  };
  double current = contrast(s.camera_T_part[k]);
  for (const bool hold_depth : {true, false}) {
    Pose T = s.camera_T_part[k];
    for (int round = 0; round < options_.settle_rounds; ++round) {
      const Pose next =
          track_region(image, s.intrinsics, *contours_[k], colors, T, map, part, options_.region, hold_depth).camera_T_part;
      const Pose step = T.inverse() * next;
      T = next;
      if (step.translation().norm() < 0.5e-3 && Eigen::AngleAxisd(step.linear()).angle() < 0.2 * M_PI / 180) break;
    }
    const double gain = hold_depth ? options_.settle_contrast_gain : options_.settle_depth_contrast_gain;
    if (const double there = contrast(T); there >= current + gain) {
      s.camera_T_part[k] = T;
      current = there;
    }
  }
}

void ModelPoseTracker::ride_back(size_t k, int frame) {
  State& s = *state_;
  auto& mine = s.tracks.samples[k];
  // The frames it was not seen in before the correction (and the follow-back's), and the last it was.
  int last = frame - 1;
  while (last >= 0 && mine[last].valid) --last;
  const int gap_end = last;
  while (last >= 0 && !mine[last].valid) --last;
  if (gap_end < 0 || last < 0) return;
  const Pose placed = mine[frame].pose;
  const Eigen::Vector3d& c = contours_[k]->centre();
  const double bottom = lowest_point_height(models_[k].mesh, placed);
  for (size_t j = 0; j < models_.size(); ++j) {
    const auto& carrier = s.tracks.samples[j];
    if (j == k || !carrier[frame].valid || !carrier[last].valid) continue;
    if ((carrier[frame].pose.translation() - carrier[last].pose.translation()).norm() < options_.hold_ride_min) continue;
    // On its top now: its lowest point there, its centre over the top.
    const auto top = carrier_top(parts_[j].extent, carrier[frame].pose);
    if (!top || std::abs(bottom - top->front().z()) > options_.ride_height || !contains_from_above(*top, placed * c))
      continue;
    const Pose on_carrier = carrier[frame].pose.inverse() * placed;
    constexpr double kRideConfidence = 0.6;  // inferred, not measured (amber in Part Tracks)
    for (int f = last + 1; f <= gap_end; ++f)
      if (carrier[f].valid) {
        mine[f].valid = true;
        mine[f].pose = carrier[f].pose * on_carrier;
        mine[f].confidence = kRideConfidence;
      }
    // Its rest before the ride, where its image put it but its depth did not: where the ride began.
    const Eigen::Vector3d eye = s.world_T_camera.translation();
    const Pose start = carrier[last].pose * on_carrier;
    const Eigen::Vector3d seen = (mine[last].pose * c - eye).normalized(), there = (start * c - eye).normalized();
    const double radius = contours_[k]->radius() / (start * c - eye).norm();
    const Eigen::Vector3d stale = mine[last].pose.translation(), carrier_at = carrier[last].pose.translation();
    // (One within the ride's tolerance was measured right: kept as measured.)
    if (std::acos(std::clamp(seen.dot(there), -1.0, 1.0)) > radius ||
        (start.translation() - stale).norm() <= options_.ride_tolerance)
      return;
    for (int f = last; f >= 0 && mine[f].valid && carrier[f].valid; --f) {
      if ((mine[f].pose.translation() - stale).norm() > options_.ride_tolerance ||
          (carrier[f].pose.translation() - carrier_at).norm() > options_.ride_tolerance)
        break;
      mine[f].pose = carrier[f].pose * on_carrier;
    }
    return;
  }
}

Eigen::Vector2d ModelPoseTracker::centre_in_image(size_t k, const Pose& camera_T_part) const {
  const PinholeIntrinsics& K = state_->intrinsics;
  const Eigen::Vector3d c = camera_T_part * contours_[k]->centre();
  return {K.fx * c.x() / c.z(), K.fy * c.y() / c.z()};
}

double ModelPoseTracker::radius_in_image(size_t k, const Pose& camera_T_part) const {
  return contours_[k]->radius() * state_->intrinsics.fx / (camera_T_part * contours_[k]->centre()).z();
}

bool ModelPoseTracker::passed_in_front(size_t k, const std::vector<bool>& moving,
                                       const std::vector<bool>& lost_moving) const {
  const State& s = *state_;
  auto disc = [&](size_t i, Eigen::Vector2d& centre, double& radius, double& depth) {
    const Eigen::Vector3d c = s.camera_T_part[i] * contours_[i]->centre();
    if (c.z() < 0.05) return false;
    centre = centre_in_image(i, s.camera_T_part[i]);
    radius = radius_in_image(i, s.camera_T_part[i]);
    depth = c.z();
    return true;
  };
  Eigen::Vector2d ck, cj;
  double rk, rj, zk, zj;
  if (!disc(k, ck, rk, zk)) return false;
  for (size_t j = 0; j < models_.size(); ++j)
    if (j != k && (moving[j] || lost_moving[j]) && disc(j, cj, rj, zj) && zj < zk && (ck - cj).norm() < rk + rj)
      return true;
  return false;
}

RegionFrameResult ModelPoseTracker::search(const cv::Mat& image, int k, const OcclusionMap& map) const {
  const State& s = *state_;
  const ContourModel& model = *contours_[k];
  const Pose& last = s.camera_T_part[k];
  const Eigen::Vector3d c = last * model.centre();
  RegionFrameResult best;
  if (c.z() < 0.05) return best;
  // Candidate poses: the last one shifted across the view on a grid of image offsets, scored by
  // their contrast; the best few are tracked from.
  const double radius_px = radius_in_image(k, last);
  const double reach = std::max(options_.search_radii * radius_px, 60.0), step = std::max(radius_px / 3, 6.0);
  std::vector<std::pair<double, Pose>> candidates;
  for (double dy = -reach; dy <= reach; dy += step)
    for (double dx = -reach; dx <= reach; dx += step) {
      Pose T = last;
      T.translation() += Eigen::Vector3d(dx * c.z() / s.intrinsics.fx, dy * c.z() / s.intrinsics.fy, 0.0);
      candidates.push_back({0.0, T});
    }
  on_search_threads(candidates.size(), 16, [&](size_t i) {
    candidates[i].first = contour_contrast(image, s.intrinsics, model, s.colors[k], candidates[i].second);
  });
  const size_t tries = std::min<size_t>(options_.search_tries, candidates.size());
  std::partial_sort(candidates.begin(), candidates.begin() + tries, candidates.end(),
                    [](auto& a, auto& b) { return a.first > b.first; });
  // At the last depth: a candidate across the view says nothing about it.
  std::vector<RegionFrameResult> tracked(tries);
  on_search_threads(tries, 1, [&](size_t i) {
    tracked[i] = track_region(image, s.intrinsics, model, s.colors[k], candidates[i].second, map, k, options_.region, true);
  });
  for (size_t i = 0; i < tries; ++i)
    if (i == 0 || tracked[i].contrast > best.contrast) best = tracked[i];
  return best;
}

bool ModelPoseTracker::seen_in(const RegionFrameResult& r, double bar) const {
  return r.contrast >= bar && r.lines > 0 && r.used_lines >= options_.lost_used_fraction * r.lines;
}

bool ModelPoseTracker::within_rest_hold(size_t k, const Pose& measured) const {
  const State& s = *state_;
  const double turn = Eigen::AngleAxisd(s.camera_T_part[k].linear().transpose() * measured.linear()).angle();
  return (centre_in_image(k, measured) - s.centres[k].back()).norm() < options_.rest_hold_px &&
         turn < options_.rest_hold_deg * M_PI / 180;
}

std::optional<RegionFrameResult> ModelPoseTracker::rest_search(const cv::Mat& image, int k, bool* where_colours_show) const {
  const State& s = *state_;
  // Scored on what the furniture and the other parts leave visible (its own stale pose hides nothing).
  const OcclusionMap map = occlusion_map(k);
  if (std::optional<RegionFrameResult> found = rest_search(image, k, map, {.radii = options_.rest_search_radii}))
    return found;
  // Not within the plain reach: the longer it has been lost, the farther it may have been
  // carried before it was put down. Beyond the plain reach only on the evidence of a part in
  // full view.
  const int frames = std::max(s.unseen[k] - options_.rest_search_growth_after, 0);
  const double radii = std::min(options_.rest_search_radii + options_.rest_search_growth * frames, options_.rest_search_max_radii);
  if (radii > options_.rest_search_radii)
    if (std::optional<RegionFrameResult> found = rest_search(image, k, map, {.radii = radii, .beyond = true})) return found;
  // Not as it stood: perhaps laid on a side (a box put down on its side), within the plain reach
  // (the search beyond it on the sides too measured slower and found nothing more).
  if (options_.rest_search_faces)
    if (std::optional<RegionFrameResult> found = rest_search(image, k, map, {.radii = options_.rest_search_radii, .other_faces = true}))
      return found;
  // Lost for a while: wherever its colours show, beyond the reach searched.
  // (Every `global_search_every` frames lost, and in the frame after a find: the whole frame costs.)
  if (!options_.global_search || s.unseen[k] < options_.global_search_after ||
      (!s.rest_find[k] && s.unseen[k] % std::max(options_.global_search_every, 1) != 0))
    return std::nullopt;
  const double radius_px = radius_in_image(k, s.camera_T_part[k]);
  const Eigen::Vector2d at = centre_in_image(k, s.camera_T_part[k]) + Eigen::Vector2d(s.intrinsics.cx, s.intrinsics.cy);
  // The blobs most like it: in its colours, and as large as it showed when last seen (the
  // furniture's or the floor's tiles in colours near its own are larger or smaller).
  const OcclusionMap all = occlusion_map();
  const double shown = cv::countNonZero(all.labels == k + 1) / (all.scale * all.scale);
  std::vector<std::pair<double, Eigen::Vector2d>> likeness;
  for (const ColorBlob& b : color_blobs(image, s.colors[k], map, k, options_.global_blob_fraction * shown))
    if ((b.centre - at).norm() > radii * radius_px)
      likeness.push_back({b.probability * std::min(b.area, shown) / std::max(b.area, shown), b.centre});
  std::sort(likeness.begin(), likeness.end(), [](auto& a, auto& b) { return a.first > b.first; });
  std::vector<Eigen::Vector2d> around;
  for (const auto& [v, centre] : likeness)
    if (around.size() < static_cast<size_t>(options_.global_search_blobs)) around.push_back(centre);
  if (around.empty()) return std::nullopt;
  std::optional<RegionFrameResult> found =
      rest_search(image, k, map, {.radii = options_.global_search_radii, .min_reach_px = 0, .around = &around});
  if (!found)
    found = rest_search(image, k, map, {.radii = options_.global_search_radii, .min_reach_px = 0, .other_faces = true, .around = &around});
  if (found && where_colours_show) *where_colours_show = true;
  return found;
}

std::optional<RegionFrameResult> ModelPoseTracker::rest_search(const cv::Mat& image, int k, const OcclusionMap& map,
                                                               const RestSearchArea& area) const {
  const State& s = *state_;
  const std::vector<SupportLevel>& supports = area.levels ? *area.levels : s.supports;
  const bool beyond = area.beyond, other_faces = area.other_faces;
  const ContourModel& model = *contours_[k];
  const Pose& last = s.camera_T_part[k];
  const Eigen::Vector3d c = last * model.centre();
  if (c.z() < 0.05) return std::nullopt;
  // Where its centre's image may be now: a grid around where it was last seen.
  const double radius_px = radius_in_image(k, last);
  const double reach = std::max(area.radii * radius_px, area.min_reach_px);
  const double base_reach = std::max(options_.rest_search_radii * radius_px, area.min_reach_px);
  const double step = std::max(radius_px / options_.rest_search_density, 6.0);
  const Eigen::Vector2d at = centre_in_image(k, last) + Eigen::Vector2d(s.intrinsics.cx, s.intrinsics.cy);
  std::vector<Eigen::Vector2d> pixels;
  for (const Eigen::Vector2d& centre : area.around ? *area.around : std::vector<Eigen::Vector2d>{at})
    for (double dy = -reach; dy <= reach; dy += step)
      for (double dx = -reach; dx <= reach; dx += step) {
        const Eigen::Vector2d p = centre + Eigen::Vector2d(dx, dy);
        if (beyond && std::max(std::abs(dx), std::abs(dy)) <= base_reach) continue;  // searched already
        if (p.x() >= 0 && p.y() >= 0 && p.x() < s.image_size.width && p.y() < s.image_size.height) pixels.push_back(p);
      }
  // Turned about the vertical from its last rest: as it was last seen (a carried part is mostly
  // put down as it was held), and evenly around that; on another face (rest_search_faces), evenly.
  const Eigen::Matrix3d rest = area.stood_level ? standing_level(s.rest_rotation[k]) : s.rest_rotation[k];
  const Eigen::Matrix3d turned = s.world_T_camera.linear() * last.linear() * rest.transpose();
  const double seen_turn = std::atan2(turned(1, 0), turned(0, 0));
  const int turn_count = std::max(options_.rest_search_turns, 1);
  const std::vector<Eigen::Matrix3d> orientations = other_faces ? laid_on_sides(rest) : std::vector<Eigen::Matrix3d>{rest};
  std::vector<RestingPart> resting;
  std::vector<RestingCandidate> candidates;
  for (size_t face = 0; face < orientations.size(); ++face) {
    resting.push_back({parts_[k].extent, centre_height(models_[k].mesh, model.centre(), orientations[face])});
    std::vector<double> turns;
    // (On its sides, half as many: the four sides are tried each.)
    const int count = other_faces ? std::max(turn_count / 2, 1) : turn_count;
    for (int i = 0; i < count; ++i) turns.push_back((other_faces ? 0.0 : seen_turn) + 2 * M_PI * i / count);
    for (RestingCandidate& c : resting_candidates(supports, resting[face], orientations[face], turns, s.world_T_camera,
                                                  s.intrinsics, pixels, furniture_)) {
      c.face = face;
      candidates.push_back(c);
    }
  }
  // Scored first over a band as wide as half the grid's step: the candidates are that far apart.
  // A candidate that shows too little of itself cannot be told from anything else.
  auto score = [&](const Pose& T, int band, int stride = 2) {
    const VisibleContrast v = visible_contrast(image, s.intrinsics, model, s.colors[k], T, map, k, 4, band, stride);
    return v.visible >= options_.rest_visible_fraction * v.lines ? v.contrast : -2.0;
  };
  std::vector<double> scores(candidates.size());
  on_search_threads(candidates.size(), 64, [&](size_t i) {
    scores[i] = score(candidates[i].camera_T_part, std::max(2, static_cast<int>(step / 8)), 4);
  });
  std::vector<std::pair<double, size_t>> scored;
  for (size_t i = 0; i < candidates.size(); ++i)
    if (scores[i] > -2.0) scored.push_back({scores[i], i});
  std::sort(scored.begin(), scored.end(), [](auto& a, auto& b) { return a.first > b.first; });
  // The best at distinct places or turns (a step apart in the image, or turned by more than an
  // eighth: a box turned half round has nearly the same outline, and only the best fit of the
  // two tells them apart), each moved along its support and turned while it then stands out
  // more (steps halving down to 2 px): the grid is too coarse for the contour's lines to pull
  // a candidate in from where it lies.
  auto same_place = [](const RestingCandidate& a, const RestingCandidate& b, double px) {
    return a.face == b.face && (a.pixel - b.pixel).norm() < px &&
           std::abs(std::remainder(a.turn - b.turn, 2 * M_PI)) < M_PI / 4;
  };
  std::vector<RestingCandidate> picked;
  for (const auto& [v, i] : scored) {
    if (picked.size() >= static_cast<size_t>(std::max(options_.rest_search_climbs, 0))) break;
    if (std::none_of(picked.begin(), picked.end(), [&](const RestingCandidate& p) { return same_place(p, candidates[i], step); }))
      picked.push_back(candidates[i]);
  }
  on_search_threads(picked.size(), 1, [&](size_t i) {
    RestingCandidate& p = picked[i];
    for (double d = step / 2, a = (other_faces ? 2 : 1) * M_PI / turn_count; d >= 2.0; d /= 2, a /= 2) {
      // Scored over a band as wide as the step: a finer one would not see the way from afar.
      const int band = std::max(2, static_cast<int>(d / 4));
      double best = score(p.camera_T_part, band);
      for (bool moved = true; moved;) {
        moved = false;
        for (const auto& [du, dv, dt] : {std::tuple{d, 0.0, 0.0}, {-d, 0.0, 0.0}, {0.0, d, 0.0}, {0.0, -d, 0.0}, {0.0, 0.0, a}, {0.0, 0.0, -a}}) {
          RestingCandidate q = p;
          q.pixel += Eigen::Vector2d(du, dv);
          q.turn += dt;
          const std::optional<Pose> T =
              resting_pose(supports[q.level].height, resting[q.face], orientations[q.face], q.turn, s.world_T_camera,
                           s.intrinsics, q.pixel);
          if (!T) continue;
          if (const double v = score(*T, band); v > best) {
            q.camera_T_part = *T;
            p = q, best = v, moved = true;
          }
        }
      }
    }
  });
  // The best few of those, at distinct places, tracked from.
  std::vector<std::pair<double, size_t>> climbed;
  for (size_t i = 0; i < picked.size(); ++i) climbed.push_back({score(picked[i].camera_T_part, 2), i});
  std::sort(climbed.begin(), climbed.end(), [](auto& a, auto& b) { return a.first > b.first; });
  std::vector<RestingCandidate> tries;
  for (const auto& [v, i] : climbed)
    if (tries.size() < static_cast<size_t>(std::max(options_.rest_search_tries, 0)) &&
        std::none_of(tries.begin(), tries.end(), [&](const RestingCandidate& q) { return same_place(picked[i], q, step / 2); }))
      tries.push_back(picked[i]);
  // Each tracked from at the support's depth: it is a better cue than the silhouette's size, half hidden.
  std::vector<RegionFrameResult> tracked(tries.size());
  on_search_threads(tries.size(), 1, [&](size_t i) {
    tracked[i] = track_region(image, s.intrinsics, model, s.colors[k], tries[i].camera_T_part, map, k, options_.region, true);
  });
  std::optional<RegionFrameResult> best;
  for (size_t i = 0; i < tries.size(); ++i) {
    const RestingCandidate& t = tries[i];
    const Eigen::Vector3d part_up = orientations[t.face].transpose().col(2);  // the part's axis up as put down
    const Pose& candidate = t.camera_T_part;
    const RegionFrameResult& r = tracked[i];
    const int visible = r.lines - r.hidden_lines;
    if (visible < options_.rest_visible_fraction * r.lines || r.used_lines < options_.rest_used_fraction * visible ||
        r.contrast < options_.rest_contrast * s.reference_contrast[k])
      continue;
    // Beyond the plain reach (grown with the time lost), on another face than it rested on, or
    // wherever its colours show (more poses tried, more chances for a wrong one to fit): only on
    // the evidence of a part in full view, standing out as clearly, or (where its colours show)
    // its print there bearing it out.
    if ((beyond || other_faces || area.around) && (r.hidden_lines > 0.1 * r.lines || r.used_lines < 0.9 * r.lines))
      continue;
    if ((beyond || other_faces || area.around) && r.contrast < options_.search_contrast * s.reference_contrast[k]) {
      if (!area.around) continue;
      const PrintDifference d = print_difference(image, s.intrinsics, s.world_T_camera, models_[k].mesh, r.camera_T_part, map, k,
                                                 options_.start_cover_difference);
      if (d.pixels == 0 || d.outliers > options_.global_print_outliers * d.pixels) continue;
    }
    // Still standing on the support it was put on: not tilted off it (off its last rest's
    // orientation, or off that stood level: rest_tilt_from_level), not lifted or sunk.
    const Eigen::Matrix3d world_R = s.world_T_camera.linear() * r.camera_T_part.linear();
    auto tilt_from = [&](const Eigen::Vector3d& up) { return std::acos(std::clamp(up.dot(world_R.transpose().col(2)), -1.0, 1.0)); };
    double tilt = tilt_from(part_up);
    if (options_.rest_tilt_from_level) tilt = std::min(tilt, tilt_from(standing_level(orientations[t.face]).transpose().col(2)));
    const double bottom = lowest_point_height(models_[k].mesh, s.world_T_camera * r.camera_T_part);
    const double support = (s.world_T_camera * candidate * model.centre()).z() - resting[t.face].lift;
    if (tilt > options_.rest_tilt_deg * M_PI / 180 || std::abs(bottom - support) > options_.rest_height_tolerance) continue;
    // The most evidence: edges found, and how clearly.
    if (!best || r.used_lines * r.contrast > best->used_lines * best->contrast) best = r;
  }
  if (best && options_.rest_search_half_turn_ratio > 0) best = by_print(image, k, map, *best);
  return best;
}

void ModelPoseTracker::recheck_rests(int frame, const cv::Mat& image, const std::vector<bool>& resting) {
  State& s = *state_;
  if (frame % std::max(options_.rest_recheck_every, 1) != 0) return;
  // Where a part can stand: the furniture, and the carriers' tops (a carrier not level has none).
  std::vector<SupportLevel> levels = s.supports;
  std::vector<size_t> carriers;  // of each level after the furniture's
  for (size_t j = 0; j < models_.size(); ++j)
    if (!parts_[j].planning)
      if (const auto top = carrier_top(parts_[j].extent, s.world_T_camera * s.camera_T_part[j])) {
        levels.push_back(support_level(*top));
        carriers.push_back(j);
      }
  const double max_tilt = options_.rest_tilt_deg * M_PI / 180;
  for (size_t k = 0; k < models_.size(); ++k) {
    // (A start is where it was placed, as the operator or an estimator put it: not rechecked.)
    if (!parts_[k].planning || !resting[k] || s.measured_at[k] != frame || s.rest_began[k] <= init_.frame) continue;
    const Eigen::Vector3d& centre = contours_[k]->centre();
    const Pose before = s.world_T_camera * s.camera_T_part[k];
    // Standing on another part (a stack) counts too: it is not looked for elsewhere then.
    std::vector<SupportLevel> under = levels;
    for (size_t j = 0; j < models_.size(); ++j)
      if (j != k && parts_[j].planning)
        if (const auto top = carrier_top(parts_[j].extent, s.world_T_camera * s.camera_T_part[j]))
          under.push_back(support_level(*top));
    if (stands_on(under, models_[k].mesh, centre, before, options_.rest_recheck_height, max_tilt)) {
      s.unplaced_checks[k] = 0;
      continue;
    }
    const int part = static_cast<int>(k);
    const OcclusionMap map = occlusion_map(part);
    const std::optional<RegionFrameResult> found =
        rest_search(image, part, map, {.radii = options_.rest_recheck_across, .min_reach_px = 0, .stood_level = true, .levels = &levels});
    // Where it shows (its depth aside, which the silhouette gives weakly), and as clearly.
    bool placed = false;
    if (found) {
      const double radius_px = radius_in_image(k, s.camera_T_part[k]);
      const double across = (centre_in_image(k, found->camera_T_part) - centre_in_image(k, s.camera_T_part[k])).norm();
      const VisibleContrast now = visible_contrast(image, s.intrinsics, *contours_[k], s.colors[k], s.camera_T_part[k], map, part);
      const VisibleContrast there = visible_contrast(image, s.intrinsics, *contours_[k], s.colors[k], found->camera_T_part, map, part);
      placed = across <= options_.rest_recheck_across * radius_px && there.contrast >= now.contrast - options_.rest_recheck_margin;
    }
    if (!placed) {
      const double above = height_above_levels(levels, models_[k].mesh, centre, before, options_.rest_recheck_height);
      s.unplaced_checks[k] = above > options_.rest_recheck_unplaced_height ? s.unplaced_checks[k] + 1 : 0;
      if (options_.rest_recheck_unplaced && s.unplaced_checks[k] >= options_.rest_recheck_unplaced_checks) lose_rest(k, frame);
      continue;
    }
    // The whole rest was there: its samples so far move with it.
    const Pose after = s.world_T_camera * found->camera_T_part;
    auto& samples = s.tracks.samples[k];
    for (int f = std::max(s.rest_began[k], 0); f <= frame; ++f)
      if (samples[f].valid) samples[f].pose = after;
    s.camera_T_part[k] = found->camera_T_part;
    s.rest_world[k] = after;
    s.rest_rotation[k] = after.linear();
    s.centres[k].assign(3, centre_in_image(k, found->camera_T_part));
    s.previous[k].reset();
    s.rest_shots[k] = {};
    std::string on = "the furniture";
    for (size_t i = 0; i < carriers.size(); ++i)
      if (stands_on({levels[s.supports.size() + i]}, models_[k].mesh, centre, after, options_.rest_recheck_height, max_tilt))
        on = "part '" + models_[carriers[i]].id + "'";
    const double moved_mm = 1e3 * (after * centre - before * centre).norm();
    warnings_.push_back("part '" + models_[k].id + "', frames " + std::to_string(s.rest_began[k]) + "-" +
                        std::to_string(frame) + ": its rest was tracked standing on nothing; it shows as well standing on " +
                        on + ", " + std::to_string(static_cast<int>(std::lround(moved_mm))) +
                        " mm away along its line of sight, and rests there");
  }
}

void ModelPoseTracker::lose_rest(size_t k, int frame) {
  State& s = *state_;
  auto& samples = s.tracks.samples[k];
  for (int f = std::max(s.rest_began[k], 0); f <= frame; ++f) samples[f].valid = false;
  warnings_.push_back("part '" + models_[k].id + "', frames " + std::to_string(s.rest_began[k]) + "-" + std::to_string(frame) +
                      ": its rest was tracked standing on nothing, and it shows standing nowhere near: taken as lost there "
                      "(something not modelled, a hand, may have held it)");
  s.seen_last[k] = false;
  s.unseen[k] = 1;
  s.centres[k].clear();
  s.previous[k].reset();
  s.rest_find[k].reset();
  s.doubted[k] = true;
  s.unplaced_checks[k] = 0;
}

RegionFrameResult ModelPoseTracker::by_print(const cv::Mat& image, int k, const OcclusionMap& map,
                                             const RegionFrameResult& found) const {
  const State& s = *state_;
  // Turned half round about the world's vertical through its centre: the same outline.
  const Eigen::Vector3d c = found.camera_T_part * contours_[k]->centre();
  const Eigen::Vector3d up = s.world_T_camera.linear().transpose() * Eigen::Vector3d::UnitZ();
  Pose turn = Pose::Identity();
  turn.linear() = Eigen::AngleAxisd(M_PI, up).toRotationMatrix();
  turn.translation() = c - turn.linear() * c;
  const Pose turned = turn * found.camera_T_part;
  const double as_found = appearance_error(image, s.intrinsics, s.world_T_camera, models_[k].mesh, found.camera_T_part, map, k);
  const double half_round = appearance_error(image, s.intrinsics, s.world_T_camera, models_[k].mesh, turned, map, k);
  if (as_found < 0 || half_round < 0 || half_round > options_.rest_search_half_turn_ratio * as_found) return found;
  // Its print says so, if its outline stands out there nearly as well as the find's (the same
  // outline, up to the mesh's own asymmetry): the find's place, turned. (Tracked on from there,
  // the centre moves with that asymmetry: tunnel_0's last rest 12.8 mm off, the find's 2.2.)
  const RegionFrameResult r = track_region(image, s.intrinsics, *contours_[k], s.colors[k], turned, map, k, options_.region, true);
  if (r.contrast < 0.9 * found.contrast || r.used_lines < 0.9 * found.used_lines) return found;
  RegionFrameResult out = found;
  out.camera_T_part = turned;
  return out;
}

void ModelPoseTracker::watch_rides(int frame, const std::vector<bool>& resting) {
  State& s = *state_;
  std::optional<std::vector<RidePart>> ride_now;  // (only when a part is not measured)
  for (size_t k = 0; k < models_.size(); ++k) {
    if (!s.rides[k] && (!resting[k] || s.measured_at[k] >= frame - 1 || frame <= init_.frame)) continue;
    if (!ride_now) ride_now = ride_parts(frame);
    if (s.rides[k] && s.rides[k]->ride.parted(*ride_now, ride_rules())) s.rides[k].reset();
    if (s.rides[k] || !resting[k] || s.measured_at[k] >= frame - 1) continue;
    const Pose rest = s.world_T_camera * s.camera_T_part[k];
    const double bottom = lowest_point_height(models_[k].mesh, rest);
    if (std::optional<Ride> ride =
            Ride::detect(k, rest * contours_[k]->centre(), bottom, contours_[k]->radius(), *ride_now, ride_rules()))
      s.rides[k] = State::Riding{std::move(*ride), rest};
  }
}

RideRules ModelPoseTracker::ride_rules() const {
  return {options_.hold_ride_min, options_.ride_tolerance, options_.ride_tolerance_fraction,
          options_.ride_height,   options_.ride_radii,     options_.ride_start_frames};
}

std::vector<RidePart> ModelPoseTracker::ride_parts(int frame) const {
  const State& s = *state_;
  std::vector<RidePart> parts(models_.size());
  for (size_t j = 0; j < parts.size(); ++j) {
    const Eigen::Vector3d& c = contours_[j]->centre();
    RidePart& p = parts[j];
    if (s.rest_world[j]) {
      p.rest = *s.rest_world[j] * c;
      p.rest_bottom = lowest_point_height(models_[j].mesh, *s.rest_world[j]);
    }
    p.left_rest = s.left_rest[j];
    p.tracked = s.measured_at[j] >= frame - 1;
    p.now = s.world_T_camera * s.camera_T_part[j] * c;
  }
  return parts;
}

void ModelPoseTracker::watch_rest_turns(int frame, const cv::Mat& image, const OcclusionMap& map,
                                        const std::vector<bool>& resting) {
  State& s = *state_;
  for (size_t k = 0; k < models_.size(); ++k) {
    PrintShot& shot = s.rest_shots[k];
    // Its rest is over (it moved, or was found or placed elsewhere): turned now.
    if (shot.frame >= 0 && !same_rest(s.camera_T_part[k], shot.camera_T_part)) turn_rest(k);
    if (s.measured_at[k] != frame || !resting[k] || frame % std::max(options_.rest_turn_every, 1) != 0 ||
        s.rest_shots[k].outliers <= options_.rest_turn_clear)
      continue;
    const PrintDifference d = print_difference(image, s.intrinsics, s.world_T_camera, models_[k].mesh, s.camera_T_part[k],
                                               map, static_cast<int>(k), options_.start_cover_difference);
    if (d.pixels < kRestTurnPixels) continue;
    const double outliers = static_cast<double>(d.outliers) / d.pixels;
    if (outliers < s.rest_shots[k].outliers) s.rest_shots[k] = {frame, image.clone(), map, s.camera_T_part[k], outliers};
  }
}

std::optional<Pose> ModelPoseTracker::turned_by_print(size_t k, const PrintShot& shot) const {
  const State& s = *state_;
  const PrintTurn fit = turn_to_print(shot.image, s.intrinsics, s.world_T_camera, models_[k].mesh, shot.camera_T_part,
                                      contours_[k]->centre(), shot.map, static_cast<int>(k));
  const Pose before = s.world_T_camera * shot.camera_T_part, after = s.world_T_camera * fit.camera_T_part;
  if (fit.error < 0 || fit.error > options_.rest_turn_ratio * fit.error_before ||
      Eigen::AngleAxisd(after.linear().transpose() * before.linear()).angle() > options_.rest_turn_max_deg * M_PI / 180)
    return std::nullopt;
  return after;
}

void ModelPoseTracker::turn_rest(size_t k) {
  State& s = *state_;
  const PrintShot shot = std::move(s.rest_shots[k]);
  s.rest_shots[k] = {};
  // Something not modelled over it (a hand) even in its clearest frame: a turn would fit that too.
  if (shot.frame < 0 || shot.outliers > options_.rest_turn_covered) return;
  const std::optional<Pose> turned = turned_by_print(k, shot);
  if (!turned) return;
  const Pose before = s.world_T_camera * shot.camera_T_part, after = *turned;
  // Every sample of that rest: the frames around the shot reported at the rest's pose.
  auto& samples = s.tracks.samples[k];
  for (const int direction : {-1, 1})
    for (int f = direction < 0 ? shot.frame : shot.frame + 1; f >= 0 && f < static_cast<int>(samples.size()); f += direction) {
      if (!samples[f].valid) continue;
      if (!same_rest(samples[f].pose, before)) break;
      samples[f].pose = after;
    }
}

void ModelPoseTracker::watch_placements(int frame, const cv::Mat& image) {
  State& s = *state_;
  for (size_t k = 0; k < models_.size(); ++k) {
    PlacementWitness& w = s.witnesses[k];
    if (!w.open) continue;
    const Eigen::Vector3d centre = contours_[k]->centre();
    if ((s.camera_T_part[k] * centre - w.camera_T_placed * centre).norm() > contours_[k]->radius()) {
      close_witness(k);
      continue;
    }
    // Tracked where it was placed: nothing to tell apart (most parts, most frames).
    if (frame % std::max(options_.rest_turn_every, 1) != 0 || same_rest(s.camera_T_part[k], w.camera_T_placed))
      continue;
    // Both poses judged alike: the part itself drawn at neither.
    const OcclusionMap map = occlusion_map(static_cast<int>(k));
    auto outliers = [&](const Pose& T) {
      const PrintDifference d = print_difference(image, s.intrinsics, s.world_T_camera, models_[k].mesh, T, map,
                                                 static_cast<int>(k), options_.start_cover_difference);
      return d.pixels < kRestTurnPixels ? -1.0 : static_cast<double>(d.outliers) / d.pixels;
    };
    const double placed = outliers(w.camera_T_placed);
    if (placed < 0) continue;
    const double tracked = outliers(s.camera_T_part[k]);
    w.look(frame, image, map, placed, tracked < 0 ? 1.0 : tracked, options_.rest_turn_covered);
  }
}

void ModelPoseTracker::close_witness(size_t k) {
  State& s = *state_;
  PlacementWitness& w = s.witnesses[k];
  if (!w.open) return;
  w.open = false;
  if (!w.borne_out(options_.rest_turn_covered, options_.witness_margin)) return;
  // Turned by its print in its clearest frame, as a rest is (turn_rest).
  Pose placed = s.world_T_camera * w.camera_T_placed;
  const PrintShot& shot = w.clearest;
  if (options_.rest_turn)
    if (const std::optional<Pose> turned = turned_by_print(k, shot)) placed = *turned;
  // From the placement to the last frame it was seen clear at, and on while the track stays
  // where it was then (the hand's pull over, the part still there).
  auto& samples = s.tracks.samples[k];
  const int last = std::min(w.last_clear, static_cast<int>(samples.size()) - 1);
  std::optional<Pose> tracked_then;
  for (int f = last; f >= w.from && !tracked_then; --f)
    if (samples[f].valid) tracked_then = samples[f].pose;
  int until = w.from;
  for (int f = w.from; f < static_cast<int>(samples.size()); ++f) {
    if (!samples[f].valid) continue;
    if (f > last && !(tracked_then && same_rest(samples[f].pose, *tracked_then))) break;
    samples[f].pose = placed;
    until = f;
  }
  // The operator is told, as of a start warned about: the track is not what is reported there.
  const double off_mm = tracked_then ? 1e3 * (tracked_then->translation() - placed.translation()).norm() : 0.0;
  warnings_.push_back(init_source_ + ": part '" + models_[k].id + "', frame " + std::to_string(shot.frame) +
                      ": shows it where it was placed at frame " + std::to_string(w.from) + " (its track " +
                      std::to_string(std::lround(off_mm)) + " mm off there, pulled by something in front of it): "
                      "frames " + std::to_string(w.from) + "-" + std::to_string(until) + " are reported at the placement");
  w.clearest = {};
}

PoseTracks ModelPoseTracker::finish() {
  if (!state_) throw std::logic_error("ModelPoseTracker::finish before start");
  // The rests still going on at the end.
  if (options_.rest_turn)
    for (size_t k = 0; k < models_.size(); ++k) turn_rest(k);
  for (size_t k = 0; k < models_.size(); ++k) close_witness(k);
  return state_->tracks;
}

std::unique_ptr<ModelPoseTracker> make_model_tracker(const MarkerScene& scene, const std::string& scene_file,
                                                     const std::string& data_dir, TrackerInit init,
                                                     std::string init_source, const ModelTrackerOptions& options) {
  std::vector<RenderMesh> meshes = marker_scene_part_meshes(scene, scene_file, data_dir);
  std::vector<ModelPart> parts;
  for (size_t k = 0; k < scene.objects.size(); ++k) parts.push_back({scene.objects[k].id, scene.objects[k].planning, std::move(meshes[k])});
  return std::make_unique<ModelPoseTracker>(std::move(parts), std::move(init), std::move(init_source),
                                            marker_scene_furniture_meshes(scene, scene_file, data_dir), options);
}

}  // namespace demoplan::perception
