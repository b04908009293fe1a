// End to end on a short synthetic video: render shelf_0, extract, compare with the truth.
// Also: the same with simulated pose-estimator and hand-detector outputs, determinism, and
// clear errors for a corrupt video and a malformed detections file. The pipeline drives
// whichever pose tracker it is given.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <optional>
#include <vector>

#include "core/error.h"
#include "core/geometry/polygon_2d.h"
#include "core/geometry/se3.h"
#include "core/scene/support.h"
#include "perception/camera/camera_model.h"
#include "perception/events/evaluation.h"
#include "perception/extraction/extract_demonstration.h"
#include "perception/extraction/tracks_file.h"
#include "perception/markers/marker_scene.h"
#include "perception/render/part_meshes.h"
#include "perception/synthetic/synthetic_video.h"
#include "perception/tracking/marker_pose_tracker.h"
#include "perception/tracking/pose_tracker.h"
#include "perception/video/video_reader.h"

namespace fs = std::filesystem;
using namespace demoplan;
using namespace demoplan::perception;

namespace {

// One synthetic video for the whole suite: rendering takes a second or two.
class Extraction : public ::testing::Test {
protected:
  static void SetUpTestSuite() {
    dir_ = fs::temp_directory_path() / ("demoplan_extraction_" + std::to_string(::getpid()));
    fs::remove_all(dir_);
    SynthOptions o;
    o.data_dir = DEMOPLAN_DATA_DIR;
    o.task = "shelf_0";
    o.robot = "panda";
    o.detections = true;
    out_ = write_synthetic_demonstration(o, (dir_ / "clean").string());
  }
  static void TearDownTestSuite() { fs::remove_all(dir_); }
  static ExtractionResult extract(const ExtractionOptions& options = {}, const std::string& video = "") {
    const MarkerScene scene = load_marker_scene(out_.scene);
    MarkerPoseTracker tracker(scene);
    return extract_demonstration(video.empty() ? out_.video : video, load_camera(out_.camera), tracker, scene.task, options);
  }
  static fs::path dir_;
  static SynthOutput out_;
};
fs::path Extraction::dir_;
SynthOutput Extraction::out_;

void expect_matches_truth(const Demonstration& d, const Demonstration& truth, double max_mm, double max_deg) {
  const DemonstrationEvaluation e = evaluate_demonstration(d, truth, 2);
  EXPECT_EQ(e.matched, e.truth_events);
  EXPECT_EQ(e.detected_events, e.truth_events);
  EXPECT_LT(e.max_translation_error_mm, max_mm);
  EXPECT_LT(e.max_rotation_error_deg, max_deg);
  EXPECT_TRUE(validate(d).empty());
}

// A tracker that looks at no image: each part rests at its A, is carried in a straight line
// from frame `grasp` to frame `release` and rests at its B (a part whose A is its B stays put);
// it records how the pipeline drives it.
struct ScriptedPart {
  TrackedPart part;
  Pose a, b;
};
class ScriptedTracker final : public PoseTracker {
public:
  ScriptedTracker(std::vector<ScriptedPart> script, int grasp, int release)
      : script_(std::move(script)), grasp_(grasp), release_(release) {
    for (const auto& p : script_) parts_.push_back(p.part);
  }
  ScriptedTracker(const Pose& a, const Pose& b, int grasp, int release)
      : ScriptedTracker({{{"YCBV_02", true, {}}, a, b}}, grasp, release) {}
  std::string name() const override { return "scripted"; }
  const std::vector<TrackedPart>& parts() const override { return parts_; }
  bool needs_images() const override { return false; }
  void start(const TrackingStart& start) override {
    ++starts;
    started_with = start;
    tracks_ = {};
    tracks_.fps = start.fps;
    for (const auto& p : parts_) {
      tracks_.object_ids.push_back(p.id);
      tracks_.planning.push_back(p.planning);
    }
    tracks_.resize(start.frames);
  }
  std::vector<PoseObservation> track(int frame, const cv::Mat& image) override {
    frames_seen.push_back(frame);
    images_given = images_given || !image.empty();
    std::vector<PoseObservation> seen;
    for (size_t k = 0; k < script_.size(); ++k) {
      PoseSample s;
      s.valid = true;
      s.confidence = 1.0;
      s.pose = interpolate(script_[k].a, script_[k].b, std::clamp(double(frame - grasp_) / (release_ - grasp_), 0.0, 1.0));
      tracks_.samples[k][frame] = s;
      seen.push_back({static_cast<int>(k), s});
    }
    return seen;
  }
  PoseTracks finish() override { return tracks_; }
  std::vector<std::string> warnings() const override { return {"init.json: part 'YCBV_02', frame 0: doubtful"}; }

  int starts = 0;
  TrackingStart started_with;
  std::vector<int> frames_seen;
  bool images_given = false;

private:
  std::vector<ScriptedPart> script_;
  int grasp_, release_;
  std::vector<TrackedPart> parts_;
  PoseTracks tracks_;
};

}  // namespace

TEST_F(Extraction, DrivesTheTrackerItIsGiven) {
  const int frames = out_.frames, grasp = frames / 4, release = frames / 2;
  const Pose a = pose_from_xyz_rpy({0.4, 0.1, 0.8}, {0, 0, 0.3});
  const Pose b = pose_from_xyz_rpy({0.6, -0.2, 1.0}, {0, 0, 1.1});
  ScriptedTracker tracker(a, b, grasp, release);
  const Camera camera = load_camera(out_.camera);
  const ExtractionResult r = extract_demonstration(out_.video, camera, tracker, "shelf_0");
  // Started once with the camera's pose, every frame in order, no image decoded for it.
  EXPECT_EQ(tracker.starts, 1);
  ASSERT_TRUE(tracker.started_with.camera.world_T_camera);
  EXPECT_TRUE(tracker.started_with.camera.world_T_camera->isApprox(*camera.world_T_camera));
  EXPECT_EQ(tracker.started_with.frames, frames);
  EXPECT_DOUBLE_EQ(tracker.started_with.fps, 30.0);
  ASSERT_EQ(static_cast<int>(tracker.frames_seen.size()), frames);
  for (int f = 0; f < frames; ++f) EXPECT_EQ(tracker.frames_seen[f], f);
  EXPECT_FALSE(tracker.images_given);
  // Its poses, not the markers', make the demonstration.
  EXPECT_EQ(r.tracker, "scripted");
  const Demonstration& d = r.demonstration;
  EXPECT_EQ(d.task, "shelf_0");
  ASSERT_EQ(d.object_ids, std::vector<std::string>{"YCBV_02"});
  ASSERT_EQ(d.events.size(), 2u);
  EXPECT_EQ(d.events[0].type, EventType::Grasp);
  EXPECT_NEAR(d.events[0].frame, grasp, 1);
  EXPECT_EQ(d.events[1].type, EventType::Release);
  EXPECT_NEAR(d.events[1].frame, release, 1);
  EXPECT_TRUE(d.events[0].poses[0].isApprox(a, 1e-9));
  EXPECT_TRUE(d.events[1].poses[0].isApprox(b, 1e-9));
  // What it warns of reaches the result (the CLI's warning lines, the GUI's status).
  EXPECT_NE(std::find(r.warnings.begin(), r.warnings.end(), "init.json: part 'YCBV_02', frame 0: doubtful"), r.warnings.end());
}

// A tray lying on a table, its depth from its image 20 mm off along the line of sight (as a part's
// a few metres away is), and a part put on it: the tray is settled on the table before the part is
// settled on its top, so the part's release is where it was put, not moved with the tray's error.
TEST_F(Extraction, APartPutOnATrayOnATableRestsOnTheSettledTray) {
  const Camera camera = load_camera(out_.camera);
  const Eigen::Vector3d eye = camera.world_T_camera->translation();
  ExtractionOptions o;
  o.scene = marker_scene_world(load_marker_scene(out_.scene), out_.scene, DEMOPLAN_DATA_DIR);
  // The table: the largest furniture support.
  std::vector<Eigen::Vector3d> table;
  auto area = [](const std::vector<Eigen::Vector3d>& p) {  // (an upward face: its plan's area)
    std::vector<Eigen::Vector2d> plan;
    for (const auto& v : p) plan.push_back(v.head<2>());
    return std::abs(polygon_area(plan));
  };
  for (const auto& s : furniture_support_polygons(*o.scene))
    if (table.empty() || area(s) > area(table)) table = s;
  ASSERT_FALSE(table.empty());
  Eigen::Vector3d middle = Eigen::Vector3d::Zero();
  for (const auto& v : table) middle += v / static_cast<double>(table.size());
  // The tray, 40 x 30 x 1.5 cm, on the table's middle; tracked 20 mm farther along its line of sight.
  const TrackedPart tray_part{"TRAY", false, Eigen::AlignedBox3d(Eigen::Vector3d(-0.2, -0.15, -0.0075), Eigen::Vector3d(0.2, 0.15, 0.0075))};
  Pose tray = Pose::Identity();
  tray.translation() = middle + Eigen::Vector3d(0, 0, 0.0075 + 0.001);
  Pose tray_seen = tray;
  tray_seen.translation() += 0.020 * (tray.translation() - eye).normalized();
  // The part from its start on the table onto the tray, tracked 10 mm nearer along its line of
  // sight there.
  const Demonstration truth = load_demonstration(out_.truth);
  const size_t k = 0;
  ASSERT_EQ(truth.object_ids[k], "YCBV_02");
  const Pose start = truth.events.front().poses[k];
  const auto object = std::find_if(o.scene->objects.begin(), o.scene->objects.end(), [](auto& so) { return so.id == "YCBV_02"; });
  ASSERT_NE(object, o.scene->objects.end());
  Eigen::Vector3d part_middle = Eigen::Vector3d::Zero();
  int corners = 0;
  for (const auto& face : object_contact_polygons(*object))
    for (const auto& v : face) part_middle += v, ++corners;
  part_middle /= corners;
  Pose put = start;
  put.translation() += Eigen::Vector3d(middle.x(), middle.y(), start.translation().z() + 0.016) - start * part_middle;
  Pose put_seen = put;
  put_seen.translation() -= 0.010 * (put * part_middle - eye).normalized();
  const int frames = out_.frames, grasp = frames / 4, release = frames / 2;
  ScriptedTracker tracker({{{"YCBV_02", true, {}}, start, put_seen}, {tray_part, tray_seen, tray_seen}}, grasp, release);
  const ExtractionResult r = extract_demonstration(out_.video, camera, tracker, "shelf_0", o);
  const auto& events = r.demonstration.events;
  ASSERT_EQ(events.size(), 2u);
  EXPECT_EQ(events[1].type, EventType::Release);
  EXPECT_LT((events[1].poses[k].translation() - put.translation()).norm(), 1e-3)
      << "released " << (events[1].poses[k].translation() - put.translation()).transpose() << " m off";
}

// The synthetic video's truth in every frame, beside truth.json as an extraction's tracks: each
// part where truth.json's events put it, and what the marker tracker reports per frame within
// millimetres of it.
TEST_F(Extraction, SynthWritesEveryPartsTruePoseInEveryFrame) {
  ASSERT_EQ(out_.truth_tracks, tracks_path_for(out_.truth));
  const TracksFile t = load_tracks_file(out_.truth_tracks);
  EXPECT_EQ(t.tracker, "truth");
  const Demonstration truth = load_demonstration(out_.truth);
  ASSERT_EQ(t.raw.object_ids, truth.object_ids);
  ASSERT_EQ(t.raw.frames, out_.frames);
  for (const auto& row : t.raw.samples)
    for (const PoseSample& s : row) ASSERT_TRUE(s.valid);
  for (const auto& e : truth.events)
    for (size_t k = 0; k < truth.object_ids.size(); ++k)
      EXPECT_TRUE(t.raw.samples[k][e.frame].pose.isApprox(e.poses[k], 1e-6)) << "frame " << e.frame << ", part " << k;
  // Carried between its grasp and release: it moves.
  const auto& grasp = truth.events.front();
  const int mid = (grasp.frame + truth.events[1].frame) / 2;
  EXPECT_GT((t.raw.samples[grasp.object][mid].pose.translation() - grasp.poses[grasp.object].translation()).norm(), 0.02);
  // The marker tracker's estimates, frame by frame.
  const ExtractionResult r = extract();
  std::vector<double> errors;
  for (size_t k = 0; k < truth.object_ids.size(); ++k)
    for (int f = 0; f < out_.frames; ++f)
      if (r.raw.samples[k][f].valid)
        errors.push_back((r.raw.samples[k][f].pose.translation() - t.raw.samples[k][f].pose.translation()).norm() * 1e3);
  ASSERT_GE(errors.size(), static_cast<size_t>(out_.frames / 2));
  std::nth_element(errors.begin(), errors.begin() + errors.size() / 2, errors.end());
  std::cout << "marker tracker, per frame: median " << errors[errors.size() / 2] << " mm over " << errors.size() << " samples\n";
  EXPECT_LT(errors[errors.size() / 2], 2.0);
}

TEST_F(Extraction, MarkerTrackerReportsEveryFrameAsItGoes) {
  const MarkerScene scene = load_marker_scene(out_.scene);
  MarkerPoseTracker tracker(scene);
  EXPECT_EQ(tracker.name(), "markers");
  ASSERT_EQ(tracker.parts().size(), scene.objects.size());
  EXPECT_EQ(tracker.parts()[0].id, scene.objects[0].id);
  EXPECT_TRUE(tracker.parts()[0].extent.isApprox(marker_extent(scene.objects[0])));
  EXPECT_TRUE(tracker.needs_images());
  VideoReader video(out_.video);
  tracker.start({load_camera(out_.camera), video.fps(), video.frame_count()});
  std::vector<std::optional<PoseSample>> live(video.frame_count());
  int seen = 0;
  for (int f = 0; f < video.frame_count(); ++f)
    for (const PoseObservation& o : tracker.track(f, video.frame(f))) {
      EXPECT_EQ(o.object, 0);
      live[f] = o.sample, ++seen;
    }
  EXPECT_GT(seen, video.frame_count() / 2);
  // finish() keeps what each frame reported, except where it settles an ambiguity.
  const PoseTracks tracks = tracker.finish();
  ASSERT_EQ(tracks.samples.size(), 1u);
  for (int f = 0; f < video.frame_count(); ++f) {
    const PoseSample& s = tracks.samples[0][f];
    EXPECT_EQ(s.valid, live[f].has_value()) << "frame " << f;
    if (live[f] && !live[f]->ambiguous) {
      EXPECT_TRUE(s.pose.isApprox(live[f]->pose, 1e-12)) << "frame " << f;
    }
  }
  // Without a marker on any part, no frame needs decoding.
  MarkerScene bare = scene;
  for (auto& o : bare.objects) o.markers.clear();
  EXPECT_FALSE(MarkerPoseTracker(bare).needs_images());
}

TEST_F(Extraction, CameraWithoutPoseOrBoardNamesTheFile) {
  Camera camera = load_camera(out_.camera);
  camera.world_T_camera.reset();
  camera.board.reset();
  ExtractionOptions o;
  o.camera_source = "cam.json";
  MarkerPoseTracker tracker(load_marker_scene(out_.scene));
  try {
    extract_demonstration(out_.video, camera, tracker, "shelf_0", o);
    FAIL() << "a camera without a pose or a board was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("cam.json: world_T_camera"), std::string::npos) << e.what();
  }
}

TEST_F(Extraction, RecoversEveryEventAndPose) {
  const Demonstration truth = load_demonstration(out_.truth);
  ASSERT_EQ(truth.events.size(), 2u);
  const ExtractionResult r = extract();
  EXPECT_EQ(r.frames, out_.frames);
  EXPECT_EQ(r.extrinsics_source, "file");
  expect_matches_truth(r.demonstration, truth, 5.0, 2.0);
  for (size_t i = 0; i < truth.events.size() && i < r.demonstration.events.size(); ++i)
    EXPECT_LE(std::abs(r.demonstration.events[i].frame - truth.events[i].frame), 2);
  // Per-frame tracks for the UI: every frame of the part has a smoothed pose.
  ASSERT_EQ(r.smoothed.samples.size(), 1u);
  for (const auto& s : r.smoothed.samples[0]) EXPECT_TRUE(s.valid);
}

TEST_F(Extraction, CameraPoseFromTheBoard) {
  ExtractionOptions o;
  o.board_extrinsics = true;
  const ExtractionResult r = extract(o);
  EXPECT_NE(r.extrinsics_source.find("board"), std::string::npos);
  const Pose truth = *load_camera(out_.camera).world_T_camera;
  EXPECT_LT((r.world_T_camera.translation() - truth.translation()).norm(), 0.02);
  expect_matches_truth(r.demonstration, load_demonstration(out_.truth), 20.0, 2.0);
}

TEST_F(Extraction, FromPoseEstimatesAndHandsOnly) {
  // A scene without markers: poses come from the BOP file, timing from the hands.
  MarkerScene scene = load_marker_scene(out_.scene);
  for (auto& o : scene.objects) o.markers.clear();
  ExtractionOptions o;
  o.bop_csv = out_.bop_csv;
  o.hands_json = out_.hands;
  MarkerPoseTracker tracker(scene);
  const ExtractionResult r = extract_demonstration(out_.video, load_camera(out_.camera), tracker, scene.task, o);
  expect_matches_truth(r.demonstration, load_demonstration(out_.truth), 15.0, 3.0);
}

TEST_F(Extraction, SameSeedSameVideo) {
  SynthOptions o;
  o.data_dir = DEMOPLAN_DATA_DIR;
  o.task = "shelf_0";
  o.time_scale = 0.25;
  o.noise_sigma = 5;
  const auto a = write_synthetic_demonstration(o, (dir_ / "a").string());
  const auto b = write_synthetic_demonstration(o, (dir_ / "b").string());
  auto bytes = [](const std::string& p) {
    std::ifstream in(p, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
  };
  EXPECT_EQ(bytes(a.truth), bytes(b.truth));
  EXPECT_EQ(bytes(a.scene), bytes(b.scene));
  VideoReader va(a.video), vb(b.video);
  ASSERT_EQ(va.frame_count(), vb.frame_count());
  EXPECT_EQ(cv::norm(va.frame(5), vb.frame(5), cv::NORM_INF), 0.0);
}

TEST_F(Extraction, CorruptVideoNamesTheFrame) {
  // A Motion-JPEG AVI cut in the middle decodes up to the cut.
  SynthOptions o;
  o.data_dir = DEMOPLAN_DATA_DIR;
  o.task = "shelf_0";
  o.time_scale = 0.25;
  o.fourcc = "MJPG";
  const auto s = write_synthetic_demonstration(o, (dir_ / "corrupt").string());
  fs::resize_file(s.video, fs::file_size(s.video) * 2 / 3);
  try {
    const MarkerScene scene = load_marker_scene(s.scene);
    MarkerPoseTracker tracker(scene);
    extract_demonstration(s.video, load_camera(s.camera), tracker, scene.task);
    FAIL() << "a truncated video was accepted";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find(s.video), std::string::npos) << what;
    EXPECT_NE(what.find("frame "), std::string::npos) << what;
  }
}

TEST_F(Extraction, MalformedDetectionsNameTheLine) {
  const std::string bad = (dir_ / "bad.csv").string();
  std::ofstream(bad) << "scene_id,im_id,obj_id,score,R,t,time\n0,0,2,0.9,1 0 0 0 1 0 0 0 1,0 0 500,-1\n0,1,2,0.9,1 0 0,0 0 500,-1\n";
  ExtractionOptions o;
  o.bop_csv = bad;
  try {
    extract(o);
    FAIL() << "a malformed detections file was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("bad.csv: line 3: R must hold 9 numbers"), std::string::npos) << e.what();
  }
}
