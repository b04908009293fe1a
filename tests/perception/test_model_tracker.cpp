// The model-based tracker: its silhouette model of a mesh, one frame of region-based tracking on
// a rendered image from a displaced start, the tracker start file, and the whole tracker on a
// synthetic video without markers.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <fstream>
#include <functional>
#include <memory>
#include <random>

#include <opencv2/videoio.hpp>

#include "core/error.h"
#include "perception/camera/camera_model.h"
#include "perception/events/evaluation.h"
#include "perception/extraction/extract_demonstration.h"
#include "perception/markers/marker_scene.h"
#include "perception/render/rasterizer.h"
#include "perception/synthetic/image_degradation.h"
#include "perception/synthetic/synthetic_video.h"
#include "perception/tracking/appearance_error.h"
#include "perception/tracking/contour_model.h"
#include "perception/tracking/contour_model_file.h"
#include "perception/tracking/model_pose_tracker.h"
#include "perception/tracking/region_pose.h"
#include "perception/tracking/ride_prediction.h"
#include "perception/tracking/tracker_init.h"

namespace fs = std::filesystem;
using namespace demoplan;
using namespace demoplan::perception;

namespace {

const Eigen::Vector3d kBox(0.06, 0.10, 0.16);

// The box's own distance to a point: 0 on its surface.
double box_surface_distance(const Eigen::Vector3d& p) {
  const Eigen::Vector3d q = p.cwiseAbs() - kBox / 2;
  const double outside = q.cwiseMax(0.0).norm();
  return outside > 0 ? outside : -q.maxCoeff();
}

// A short rendered clip of the red box before a grey-blue gradient (camera = world), with a
// grey board held right in front of the camera in the frames `covered` says.
struct Clip {
  PinholeIntrinsics K{900, 900, 320, 240};
  cv::Size size{640, 480};
  std::vector<Pose> truth;
  std::vector<cv::Mat> frames;

  Camera camera() const {
    Camera c;
    c.image_size = size;
    c.fx = K.fx, c.fy = K.fy, c.cx = K.cx, c.cy = K.cy;
    c.world_T_camera = Pose::Identity();
    return c;
  }
};

Pose box_pose(double x, double y, double z) {
  Pose p = Pose::Identity();
  p.linear() = (Eigen::AngleAxisd(0.5, Eigen::Vector3d::UnitY()) * Eigen::AngleAxisd(-0.4, Eigen::Vector3d::UnitX())).toRotationMatrix();
  p.translation() << x, y, z;
  return p;
}

Clip render_clip(const std::vector<Pose>& truth, const std::vector<bool>& covered) {
  Clip clip;
  clip.truth = truth;
  const RenderMesh box = box_mesh(kBox, {40, 40, 200}), board = box_mesh({0.4, 0.4, 0.01}, {128, 128, 128});
  Pose board_pose = Pose::Identity();
  board_pose.translation() << 0.0, 0.0, 0.3;
  for (size_t f = 0; f < truth.size(); ++f) {
    Rasterizer r(clip.size, clip.K.fx, clip.K.fy, clip.K.cx, clip.K.cy, Pose::Identity());
    r.clear({180, 160, 150}, {120, 110, 100});
    r.draw(box, truth[f]);
    if (covered[f]) r.draw(board, board_pose);
    clip.frames.push_back(r.color().clone());
  }
  return clip;
}

// The box tracked through the clip from `start` (its pose at frame 0), placed again where
// `corrections` say.
PoseTracks track_clip(const Clip& clip, const Pose& start, ModelTrackerOptions o = {},
                      const std::vector<PartCorrection>& corrections = {}) {
  TrackerInit init;
  init.parts.push_back({"box", start});
  init.corrections = corrections;
  o.contour.views = 300;
  ModelPoseTracker tracker({{"box", true, box_mesh(kBox, {40, 40, 200})}}, init, "init.json", {}, o);
  tracker.start({clip.camera(), 30.0, static_cast<int>(clip.frames.size())});
  for (size_t f = 0; f < clip.frames.size(); ++f) tracker.track(static_cast<int>(f), clip.frames[f]);
  return tracker.finish();
}

double error_mm(const PoseSample& s, const Pose& truth) { return (s.pose.translation() - truth.translation()).norm() * 1e3; }

TEST(ContourModel, PointsLieOnTheSilhouetteOfTheMesh) {
  ContourModelOptions o;
  o.views = 60;
  const ContourModel model(box_mesh(kBox, {0, 0, 255}), o);
  ASSERT_EQ(model.views().size(), 60u);
  EXPECT_NEAR(model.radius(), kBox.norm() / 2, 1e-6);
  for (const auto& v : model.views()) {
    EXPECT_GT(v.points.size(), 150u);
    for (const auto& p : v.points) {
      // On the surface (within a rendered pixel: about 1 mm here) ...
      EXPECT_LT(std::abs(box_surface_distance(p.position.cast<double>())), 1.5e-3);
      // ... with a normal across the line of sight, pointing away from the centre's projection.
      EXPECT_LT(std::abs(p.normal.dot(v.direction)), 1e-5);
      const Eigen::Vector3f off_axis = p.position - p.position.dot(v.direction) * v.direction;
      EXPECT_GT(p.normal.dot(off_axis), 0.f);
      EXPECT_GT(p.inner, 0.f);
    }
  }
  const Eigen::Vector3d up(0.1, 0.2, 1.0);
  const ContourView& nearest = model.nearest_view(up);
  for (const auto& v : model.views()) EXPECT_LE(v.direction.dot(up.normalized().cast<float>()), nearest.direction.dot(up.normalized().cast<float>()));
}

// nearest_view looks only at the views that can be nearest in a cell of directions: it must
// answer as a look at every view does (the largest dot, the first of equal ones), on the cells'
// edges and corners too.
TEST(ContourModel, NearestViewIsTheViewALookAtEveryViewFinds) {
  for (const int n : {642, 60, 7}) {
    std::vector<ContourView> views;
    for (const auto& d : sphere_directions(n)) views.push_back({d.cast<float>(), {}});
    const ContourModel model(views, Eigen::Vector3d::Zero(), 0.1);
    std::vector<Eigen::Vector3d> asked;
    std::mt19937 random(7);
    std::normal_distribution<double> normal;
    for (int i = 0; i < 100000; ++i) asked.emplace_back(normal(random), normal(random), normal(random));
    for (const double a : {-1.0, -0.75, -0.5, 0.0, 0.25, 0.5, 1.0})  // on cell boundaries (8 cells an edge)
      for (const double b : {-1.0, -0.25, 0.0, 0.75, 1.0})
        for (const double sign : {-1.0, 1.0}) {
          asked.emplace_back(sign, a, b), asked.emplace_back(a, sign, b), asked.emplace_back(a, b, sign);
          asked.emplace_back(sign * 3.0, a * 3.0, b * 3.0);  // not unit
        }
    for (const auto& v : views) asked.push_back(v.direction.cast<double>());  // exact ties with a view
    for (const auto& d : asked) {
      const Eigen::Vector3f u = d.normalized().cast<float>();
      size_t best = 0;
      for (size_t i = 1; i < views.size(); ++i)
        if (views[i].direction.dot(u) > views[best].direction.dot(u)) best = i;
      ASSERT_EQ(&model.nearest_view(d), &model.views()[best]) << n << " views, direction " << d.transpose();
    }
    EXPECT_EQ(&model.nearest_view(Eigen::Vector3d::Zero()), &model.views()[0]);
  }
}

TEST(ContourModelFile, ReadsBackWhatItWroteAndNothingElse) {
  const fs::path dir = fs::temp_directory_path() / ("demoplan_contours_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  ContourModelOptions o;
  o.views = 20;
  const RenderMesh box = box_mesh(kBox, {0, 0, 255});
  const std::uint64_t key = contour_model_key(box, o);
  EXPECT_FALSE(read_contour_model(dir.string(), key));  // nothing there yet
  const ContourModel built = cached_contour_model(box, o, dir.string());
  const auto back = read_contour_model(dir.string(), key);
  ASSERT_TRUE(back);
  ASSERT_EQ(back->views().size(), built.views().size());
  EXPECT_EQ(back->centre(), built.centre());
  EXPECT_EQ(back->radius(), built.radius());
  for (size_t v = 0; v < built.views().size(); ++v) {
    ASSERT_EQ(back->views()[v].points.size(), built.views()[v].points.size());
    for (size_t p = 0; p < built.views()[v].points.size(); ++p) {
      EXPECT_EQ(back->views()[v].points[p].position, built.views()[v].points[p].position);
      EXPECT_EQ(back->views()[v].points[p].outer, built.views()[v].points[p].outer);
    }
  }
  // Another mesh or other options: another key, no stale model.
  ContourModelOptions more = o;
  more.points = 100;
  EXPECT_NE(contour_model_key(box, more), key);
  EXPECT_NE(contour_model_key(box_mesh(kBox * 1.01, {0, 0, 255}), o), key);
  // A damaged file is not read.
  const auto file = *fs::directory_iterator(dir);
  fs::resize_file(file.path(), fs::file_size(file.path()) / 2);
  EXPECT_FALSE(read_contour_model(dir.string(), key));
  fs::remove_all(dir);
}

TEST(RegionTracking, RecoversAPoseFromADisplacedStart) {
  // A red box before a grey-blue gradient, 0.9 m from the camera; tracking starts 12 mm and
  // 4 degrees away.
  const PinholeIntrinsics K{900, 900, 320, 240};
  Pose truth = Pose::Identity();
  truth.linear() = (Eigen::AngleAxisd(0.5, Eigen::Vector3d::UnitY()) * Eigen::AngleAxisd(-0.4, Eigen::Vector3d::UnitX())).toRotationMatrix();
  truth.translation() << 0.02, -0.01, 0.9;
  const RenderMesh box = box_mesh(kBox, {40, 40, 200});
  Rasterizer r(cv::Size(640, 480), K.fx, K.fy, K.cx, K.cy, Pose::Identity());
  r.clear({180, 160, 150}, {120, 110, 100});
  r.draw(box, truth);
  const cv::Mat image = r.color().clone();

  ContourModelOptions co;
  co.views = 400;
  const ContourModel model(box, co);
  ColorHistograms colors;
  learn_colors(image, K, model, truth, {}, 0, colors);
  ASSERT_TRUE(colors.initialised());
  const Eigen::Vector3d centre = *r.project(truth.translation());
  EXPECT_GT(colors.foreground_probability(image.at<cv::Vec3b>(int(centre.y()), int(centre.x()))), 0.9f);  // the box, shaded
  int y = int(centre.y());
  while (y > 0 && std::isfinite(r.depth().at<float>(y, int(centre.x())))) --y;
  EXPECT_LT(colors.foreground_probability(image.at<cv::Vec3b>(y - 5, int(centre.x()))), 0.1f);  // above the box

  Pose start = truth;
  start.translation() += Eigen::Vector3d(0.012, -0.008, 0.0);
  start.linear() = Eigen::AngleAxisd(4.0 * M_PI / 180, Eigen::Vector3d(1, 1, 0).normalized()).toRotationMatrix() * start.linear();
  const RegionFrameResult result = track_region(image, K, model, colors, start, {}, 0);
  const Pose error = truth.inverse() * result.camera_T_part;
  EXPECT_LT((result.camera_T_part.translation() - truth.translation()).head<2>().norm(), 1.5e-3);  // across the view
  EXPECT_LT(std::abs(result.camera_T_part.translation().z() - truth.translation().z()), 8e-3);    // depth, from the size
  EXPECT_LT(Eigen::AngleAxisd(error.linear()).angle() * 180 / M_PI, 1.5);
  EXPECT_GT(result.contrast, 0.8);
  EXPECT_GT(result.used_lines, result.lines / 2);
}

TEST(TrackerInit, RoundTripsAndNamesWhatIsWrong) {
  const fs::path dir = fs::temp_directory_path() / ("demoplan_tracker_init_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  TrackerInit init;
  init.frame = 3;
  Pose p = Pose::Identity();
  p.translation() << 0.1, 0.2, 0.3;
  init.parts.push_back({"YCBV_02", p});
  save_tracker_init((dir / "init.json").string(), init);
  const TrackerInit back = load_tracker_init((dir / "init.json").string());
  EXPECT_EQ(back.frame, 3);
  ASSERT_NE(back.find("YCBV_02"), nullptr);
  EXPECT_TRUE(back.find("YCBV_02")->world_T_object.isApprox(p, 1e-12));
  EXPECT_EQ(back.find("YCBV_05"), nullptr);

  std::ofstream((dir / "twice.json").string())
      << R"({"format": "demoplan-tracker-init", "version": 1, "parts": [
        {"id": "A", "world_T_object": {"t": [0, 0, 0], "q": [0, 0, 0, 1]}},
        {"id": "A", "world_T_object": {"t": [0, 0, 0], "q": [0, 0, 0, 1]}}]})";
  try {
    load_tracker_init((dir / "twice.json").string());
    FAIL() << "a part given twice was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("parts[1].id"), std::string::npos) << e.what();
  }
  // A part of the scene the start file does not place: named.
  try {
    ModelPoseTracker tracker({{"YCBV_05", true, box_mesh(kBox, {0, 0, 255})}}, back, "init.json");
    FAIL() << "a part without a start pose was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("YCBV_05"), std::string::npos) << e.what();
  }

  // The operator's corrections: read back in their order; wrong ones named by their field.
  init.corrections.push_back({"YCBV_02", 40, p});
  init.corrections.push_back({"YCBV_02", 7, Pose::Identity()});
  save_tracker_init((dir / "corrected.json").string(), init);
  const TrackerInit corrected = load_tracker_init((dir / "corrected.json").string());
  ASSERT_EQ(corrected.corrections.size(), 2u);
  EXPECT_EQ(corrected.corrections[0].id, "YCBV_02");
  EXPECT_EQ(corrected.corrections[0].frame, 40);
  EXPECT_TRUE(corrected.corrections[0].world_T_object.isApprox(p, 1e-12));
  EXPECT_EQ(corrected.corrections[1].frame, 7);
  const std::string pose = R"("world_T_object": {"t": [0, 0, 0], "q": [0, 0, 0, 1]})";
  const std::string start = R"({"format": "demoplan-tracker-init", "version": 1, "frame": 5, "parts": [{"id": "A", )" + pose + "}], ";
  for (const auto& [corrections, field] : std::vector<std::pair<std::string, std::string>>{
           {R"([{"id": "B", "frame": 9, )" + pose + "}]", "corrections[0].id"},
           {R"([{"id": "A", "frame": 5, )" + pose + "}]", "corrections[0].frame"},
           {R"([{"id": "A", "frame": 9, )" + pose + R"(}, {"id": "A", "frame": 9, )" + pose + "}]", "corrections[1].frame"},
           {R"([{"id": "A", "frame": 9, "world_T_object": {"t": [0, 0]}}])", "corrections[0].world_T_object"}}) {
    std::ofstream((dir / "bad.json").string()) << start << R"("corrections": )" << corrections << "}";
    try {
      load_tracker_init((dir / "bad.json").string());
      ADD_FAILURE() << "accepted: " << corrections;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(field), std::string::npos) << e.what();
    }
  }
  // A correction of a part the scene does not track.
  TrackerInit stray = back;
  stray.parts.push_back({"YCBV_05", p});
  stray.corrections.push_back({"YCBV_05", 9, p});
  try {
    ModelPoseTracker tracker({{"YCBV_02", true, box_mesh(kBox, {0, 0, 255})}}, stray, "init.json");
    FAIL() << "a correction of a part not tracked was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("corrections[0].id"), std::string::npos) << e.what();
  }
  fs::remove_all(dir);
}

// shelf_0 without markers: one part carried from the table to the shelf.
TEST(ModelTracker, FollowsThePartsOfAVideoWithoutMarkers) {
  const fs::path dir = fs::temp_directory_path() / ("demoplan_model_tracker_" + std::to_string(::getpid()));
  SynthOptions o;
  o.data_dir = DEMOPLAN_DATA_DIR;
  o.task = "shelf_0";
  o.part_markers = false;
  const SynthOutput s = write_synthetic_demonstration(o, dir.string());
  const MarkerScene scene = load_marker_scene(s.scene);
  for (const auto& obj : scene.objects) EXPECT_TRUE(obj.markers.empty());
  const auto tracker = make_model_tracker(scene, s.scene, DEMOPLAN_DATA_DIR, load_tracker_init(s.init), s.init);
  const ExtractionResult r = extract_demonstration(s.video, load_camera(s.camera), *tracker, scene.task);
  EXPECT_EQ(r.tracker, "model");
  const DemonstrationEvaluation e = evaluate_demonstration(r.demonstration, load_demonstration(s.truth), 2);
  EXPECT_EQ(e.matched, e.truth_events);
  EXPECT_EQ(e.detected_events, e.truth_events);
  EXPECT_LT(e.median_translation_error_mm, 10.0);
  EXPECT_LT(e.median_rotation_error_deg, 3.0);
  fs::remove_all(dir);
}

// waiter_0 rendered without markers (with `adjust` applied to its options: another task, a
// condition), extracted with the model tracker as `extract` does it; the folder is removed with it.
struct TaskVideo {
  fs::path dir;
  SynthOutput s;
  MarkerScene scene;
  ExtractionOptions eo;

  explicit TaskVideo(const std::string& name, const std::function<void(SynthOptions&)>& adjust = {})
      : dir(fs::temp_directory_path() / ("demoplan_model_tracker_" + name + "_" + std::to_string(::getpid()))) {
    SynthOptions o;
    o.data_dir = DEMOPLAN_DATA_DIR;
    o.task = "waiter_0";
    o.robot = "kmr_iiwa";
    o.part_markers = false;
    if (adjust) adjust(o);
    s = write_synthetic_demonstration(o, dir.string());
    scene = load_marker_scene(s.scene);
    eo.scene = marker_scene_world(scene, s.scene, DEMOPLAN_DATA_DIR);
  }
  ~TaskVideo() { fs::remove_all(dir); }
  std::unique_ptr<PoseTracker> tracker(const ModelTrackerOptions& options) const {
    return make_model_tracker(scene, s.scene, DEMOPLAN_DATA_DIR, load_tracker_init(s.init), s.init, options);
  }
  ExtractionResult extraction(const ModelTrackerOptions& options = {}) const {
    return extract_demonstration(s.video, load_camera(s.camera), *tracker(options), scene.task, eo);
  }
  Demonstration extract(const ModelTrackerOptions& options = {}) const { return extraction(options).demonstration; }
};

// The first event of `type` of part `id` after `frame`; null when there is none.
const ContactEvent* event_after(const Demonstration& d, const std::string& id, EventType type, int frame = -1) {
  const auto part = std::find(d.object_ids.begin(), d.object_ids.end(), id) - d.object_ids.begin();
  for (const auto& e : d.events)
    if (e.object == part && e.type == type && e.frame > frame) return &e;
  return nullptr;
}
const ContactEvent* release_after(const Demonstration& d, const std::string& id, int frame = -1) {
  return event_after(d, id, EventType::Release, frame);
}

// waiter_0 without markers: a box seen from the front changes its outline little as it turns
// about the vertical, and the region tracker leaves its rests some degrees off that way; each
// rest turned by its print (rest_turn) is within a degree, where, tracked alone, half of them are
// more than 2 degrees off. Nothing else changes: the same events, the same places. (Without the
// rest recheck, which stands the rests it finds on nothing level and turned as they show: with
// it, most rests are within a degree either way.)
TEST(ModelTracker, RestsAreTurnedTheWayTheirPrintsShow) {
  const TaskVideo video("waiter_turn");
  const Demonstration truth = load_demonstration(video.s.truth);
  ModelTrackerOptions as_tracked;
  as_tracked.rest_recheck = false;
  ModelTrackerOptions outline_only = as_tracked;
  outline_only.rest_turn = false;
  const DemonstrationEvaluation turned = evaluate_demonstration(video.extract(as_tracked), truth, 2);
  const DemonstrationEvaluation kept = evaluate_demonstration(video.extract(outline_only), truth, 2);
  EXPECT_EQ(turned.matched, kept.matched);
  EXPECT_EQ(turned.detected_events, kept.detected_events);
  EXPECT_NEAR(turned.median_translation_error_mm, kept.median_translation_error_mm, 0.1);
  EXPECT_LT(turned.median_rotation_error_deg, 1.0);
  EXPECT_GT(kept.median_rotation_error_deg, 2.0) << "the outline alone turned the rests right: the test shows nothing";
}

// waiter_0 without markers: the demonstrator's forearm hides the sugar box in the start frame, so
// the colours learnt there are the arm's and its outline follows the arm 39 mm off (and 26
// degrees turned) until it is lifted at 25. From frame 12 the frames show it clear where it was
// placed (witness_placements): its rest until the lift is reported there, within 2 mm and a
// degree of the truth, and the operator is told so. The events stay as they are.
TEST(ModelTracker, AStartTheHandCoveredIsReportedWhereTheFramesAfterShowIt) {
  const TaskVideo video("witness");
  const Demonstration truth = load_demonstration(video.s.truth);
  ModelTrackerOptions tracked_only;
  tracked_only.witness_placements = false;
  const ExtractionResult r = extract_demonstration(video.s.video, load_camera(video.s.camera), *video.tracker({}),
                                                   video.scene.task, video.eo);
  const Demonstration& witnessed = r.demonstration;
  const Demonstration tracked = video.extract(tracked_only);
  // The operator is told which frames are reported at the placement, and why.
  EXPECT_TRUE(std::any_of(r.warnings.begin(), r.warnings.end(), [](const std::string& w) {
    return w.find("part 'YCBV_03', frame 12: shows it where it was placed at frame 0") != std::string::npos &&
           w.find("frames 0-25 are reported at the placement") != std::string::npos;
  }));
  EXPECT_EQ(evaluate_demonstration(witnessed, truth, 2).matched, evaluate_demonstration(tracked, truth, 2).matched);
  const ContactEvent* expected = event_after(truth, "YCBV_03", EventType::Grasp);
  ASSERT_TRUE(expected);
  const auto sugar = static_cast<size_t>(expected->object);
  auto errors = [&](const Demonstration& d) {
    const ContactEvent* e = event_after(d, "YCBV_03", EventType::Grasp);
    EXPECT_TRUE(e && std::abs(e->frame - expected->frame) <= 2) << "the sugar box's first grasp was not detected";
    if (!e) return std::pair{1e9, 1e9};
    const Pose& a = e->poses[sugar];
    const Pose& b = expected->poses[sugar];
    return std::pair{1e3 * (a.translation() - b.translation()).norm(),
                     Eigen::AngleAxisd(a.linear().transpose() * b.linear()).angle() * 180 / M_PI};
  };
  const auto [placed_mm, placed_deg] = errors(witnessed);
  const auto [tracked_mm, tracked_deg] = errors(tracked);
  EXPECT_LT(placed_mm, 2.0);
  EXPECT_LT(placed_deg, 1.0);
  EXPECT_GT(tracked_mm, 20.0) << "tracked alone, the start rest was right: the test shows nothing";
  std::cout << "sugar box's start rest: " << placed_mm << " mm, " << placed_deg << " deg (tracked alone: " << tracked_mm
            << " mm, " << tracked_deg << " deg)\n";
}

// shelf_1 without markers, a pole passing in front of the carried parts: the mustard, set down
// at 48, is lost at its rest from 54 as the hand passes over it to the cracker box, and the
// frames tracked on from its rest pull it 70-215 mm onto the cracker box's edge at a contrast
// just over the tracked bar (0.60 against 0.59 at 68). Lost at rest, it is taken elsewhere only
// on a find's evidence (stale_jump_radii): its release rest stays within 5 mm of the truth's, where
// taken on the tracked bar it was 192 mm off. The events stay as they are.
TEST(ModelTracker, APartLostAtRestIsNotPulledAwayFromItByAFrameTrackedOn) {
  const TaskVideo video("stale", [](SynthOptions& o) {
    o.task = "shelf_1";
    o.robot = "panda";
    o.occlusion = true;
  });
  const Demonstration truth = load_demonstration(video.s.truth);
  ModelTrackerOptions pulled;
  pulled.stale_jump_radii = 1e9;
  const Demonstration refused = video.extract(), taken = video.extract(pulled);
  EXPECT_EQ(evaluate_demonstration(refused, truth, 2).matched, evaluate_demonstration(taken, truth, 2).matched);
  const ContactEvent* expected = release_after(truth, "YCBV_05");
  ASSERT_TRUE(expected);
  const auto mustard = static_cast<size_t>(expected->object);
  auto error_mm = [&](const Demonstration& d) {
    const ContactEvent* e = release_after(d, "YCBV_05");
    EXPECT_TRUE(e && std::abs(e->frame - expected->frame) <= 2) << "the mustard's release was not detected";
    return e ? 1e3 * (e->poses[mustard].translation() - expected->poses[mustard].translation()).norm() : 1e9;
  };
  const double refused_mm = error_mm(refused), taken_mm = error_mm(taken);
  EXPECT_LT(refused_mm, 5.0);
  EXPECT_GT(taken_mm, 50.0) << "taken on the tracked bar, the rest was right: the test shows nothing";
  std::cout << "the mustard's release rest: " << refused_mm << " mm (pulled away: " << taken_mm << " mm)\n";
}

// waiter_0 without markers: the sugar box, lifted fast off the tray (its first frame up 37 px,
// before the grey floor instead of the tray) and put on the shelf's top 25 cm higher in the
// image, is followed through the carry (near_used_fraction: taken by the search only on a find
// elsewhere's clearer contrast, it was lost at the lift and found at 110 on another board
// 366 mm off), to a rest within 15 mm of the truth's. The hand setting it down drags its estimate
// 8-16 cm off until 106; the frames before its rest showed it there already from 104, the
// truth's release (date_rests_back; without, the release is dated 107). The cracker box laid
// down at 57 has its outline dragged by the withdrawing hand until 60: dated at 57 too.
TEST(ModelTracker, APartLiftedFastOffATrayIsFollowedToTheShelfAndItsReleaseDated) {
  const TaskVideo video("waiter");
  const Demonstration d = video.extract();
  const Demonstration truth = load_demonstration(video.s.truth);
  const ContactEvent* detected = release_after(d, "YCBV_03", 90);
  const ContactEvent* expected = release_after(truth, "YCBV_03", 90);
  ASSERT_TRUE(expected);
  ASSERT_TRUE(detected) << "the sugar box's last release was not detected";
  EXPECT_LE(std::abs(detected->frame - expected->frame), 1);
  const auto sugar = static_cast<size_t>(detected->object);
  EXPECT_LT((detected->poses[sugar].translation() - expected->poses[sugar].translation()).norm(), 0.015);
  // (Without the rest recheck, which moves the rests found standing on nothing, and so the
  // frames dated to them, too.)
  ModelTrackerOptions late;
  late.date_rests_back = false;
  late.rest_recheck = false;
  const Demonstration undated = video.extract(late);
  const ContactEvent* later = release_after(undated, "YCBV_03", 90);
  ASSERT_TRUE(later);
  EXPECT_GE(later->frame, expected->frame + 3);
  // The cracker box laid down at 57 while the hand withdraws over it (its outline dragged along
  // until 60): dated where the rest shows it at least as well as the dragged estimate did.
  const ContactEvent* box_truth = release_after(truth, "YCBV_02");
  const ContactEvent* box_detected = release_after(d, "YCBV_02");
  ASSERT_TRUE(box_truth);
  ASSERT_TRUE(box_detected);
  EXPECT_LE(std::abs(box_detected->frame - box_truth->frame), 1);
  ModelTrackerOptions tracked_only;
  tracked_only.date_rests_back_by_contrast = false;
  tracked_only.rest_recheck = false;
  const Demonstration tracked = video.extract(tracked_only);
  const ContactEvent* box_late = release_after(tracked, "YCBV_02");
  ASSERT_TRUE(box_late);
  EXPECT_GE(box_late->frame, box_truth->frame + 3);
}

// waiter_0 without markers: the mustard set on the tray (no furniture under it, 2.4 m from the
// camera) is measured 54 mm off along its line of sight, as small parts are that far away; with
// the tray followed as a part (synth gives it by its box) its rest settles on the tray's top.
TEST(ModelTracker, APartSetOnATrayRestsOnTheTraysTop) {
  const TaskVideo video("tray");
  const auto tray = std::find_if(video.scene.objects.begin(), video.scene.objects.end(), [](auto& o) { return !o.planning; });
  ASSERT_NE(tray, video.scene.objects.end()) << "synth --no-markers gives the tray as a part";
  ASSERT_TRUE(tray->box);
  EXPECT_NEAR(tray->box->z(), 0.015, 1e-9);
  const Demonstration truth = load_demonstration(video.s.truth);
  const ContactEvent* expected = release_after(truth, "YCBV_05");
  ASSERT_TRUE(expected);
  auto mustard_error = [&](const Demonstration& d) {
    const ContactEvent* e = release_after(d, "YCBV_05");
    if (!e || std::abs(e->frame - expected->frame) > 2) return 1.0;
    const auto k = static_cast<size_t>(e->object);
    return (e->poses[k].translation() - expected->poses[k].translation()).norm();
  };
  EXPECT_LT(mustard_error(video.extract()), 0.005);
  // Without the tray among the parts, nothing holds the mustard's depth.
  MarkerScene without = video.scene;
  without.objects.erase(without.objects.begin() + (tray - video.scene.objects.begin()));
  TrackerInit init = load_tracker_init(video.s.init);
  std::erase_if(init.parts, [&](const PartStart& p) { return p.id == tray->id; });
  const auto untrayed = make_model_tracker(without, video.s.scene, DEMOPLAN_DATA_DIR, init, video.s.init, {});
  const ExtractionResult r = extract_demonstration(video.s.video, load_camera(video.s.camera), *untrayed, without.task, video.eo);
  EXPECT_GT(mustard_error(r.demonstration), 0.03);
}

// waiter_0 without markers: after the tray's ride (65-74), its image alone puts it 27 mm too far
// along its line of sight, 2.4 m away, and the parts on it settled onto its top took that over
// (the largest rest error of the video). The ride fitted to where the three parts on it show
// (fit_rides) puts them within a centimetre; every event stays the same.
TEST(ModelTracker, ThePartsOnATrayRestWhereItsRideTookThem) {
  const TaskVideo video("ride");
  const Demonstration truth = load_demonstration(video.s.truth);
  const auto tracker = video.tracker({});
  const ExtractionResult fitted = extract_demonstration(video.s.video, load_camera(video.s.camera), *tracker, video.scene.task, video.eo);
  ExtractionOptions unfitted_options = video.eo;
  unfitted_options.fit_rides = false;
  const auto again = video.tracker({});
  const ExtractionResult unfitted = extract_demonstration(video.s.video, load_camera(video.s.camera), *again, video.scene.task, unfitted_options);
  const DemonstrationEvaluation with = evaluate_demonstration(fitted.demonstration, truth, 2);
  const DemonstrationEvaluation without = evaluate_demonstration(unfitted.demonstration, truth, 2);
  EXPECT_EQ(with.matched, 12);
  EXPECT_EQ(with.detected_events, without.detected_events);
  EXPECT_LT(with.max_translation_error_mm, 12.0);
  EXPECT_GT(without.max_translation_error_mm, 20.0) << "the parts on the tray were right without the fit: the test shows nothing";
  // The grasp of the mustard off the tray after the ride: where it rode to.
  const ContactEvent* grasp = event_after(fitted.demonstration, "YCBV_05", EventType::Grasp, 80);
  const ContactEvent* expected = event_after(truth, "YCBV_05", EventType::Grasp, 80);
  ASSERT_TRUE(grasp && expected);
  const auto k = static_cast<size_t>(grasp->object);
  EXPECT_LT((grasp->poses[k].translation() - expected->poses[k].translation()).norm(), 0.012);
}

// waiter_0 with the occluder: the cracker box, standing while carried, is lost behind the
// occluder and laid on its side on the table (57): the rest search finds it there only when it
// tries the part's other faces.
TEST(ModelTracker, ABoxLaidOnItsSideWhileHiddenIsFoundThere) {
  const TaskVideo video("side", [](SynthOptions& o) { o.occlusion = true; });
  const Demonstration truth = load_demonstration(video.s.truth);
  const ContactEvent* first_release = release_after(truth, "YCBV_02");
  ASSERT_TRUE(first_release);
  const auto box = first_release->object;
  // Laid on its side: its up axis is horizontal at the release.
  ASSERT_LT(std::abs(first_release->poses[box].linear()(2, 2)), 0.1);
  const auto released_there = [&](const Demonstration& d) {
    return std::any_of(d.events.begin(), d.events.end(), [&](const ContactEvent& e) {
      return e.object == box && e.type == EventType::Release && std::abs(e.frame - first_release->frame) <= 2 &&
             (e.poses[box].translation() - first_release->poses[box].translation()).norm() < 0.015;
    });
  };
  EXPECT_TRUE(released_there(video.extract()));
  ModelTrackerOptions standing_only;
  standing_only.rest_search_faces = false;
  EXPECT_FALSE(released_there(video.extract(standing_only)));
}

// waiter_0 with the occluder: the sugar box, carried behind the pole onto the tray, comes to
// rest tracked 17 cm deep along its line of sight and 18 degrees tilted, its image in place: a
// rest that stands on nothing. Looked for where it could stand (rest_recheck), it is found on
// the tray's top; so it is followed on the tray's ride and its next carry (95-104) is seen.
TEST(ModelTracker, ARestStandingOnNothingIsFoundWhereItCouldStand) {
  const TaskVideo video("recheck", [](SynthOptions& o) { o.occlusion = true; });
  const Demonstration truth = load_demonstration(video.s.truth);
  const ContactEvent* put_on_tray = release_after(truth, "YCBV_03");
  const ContactEvent* next_grasp = event_after(truth, "YCBV_03", EventType::Grasp, 80);
  ASSERT_TRUE(put_on_tray && next_grasp);
  const auto sugar = static_cast<size_t>(put_on_tray->object);
  // The sugar box's rest on the tray (m; a large number when its release is not found).
  const auto rest_error = [&](const Demonstration& d) {
    for (const auto& e : d.events)
      if (e.object == put_on_tray->object && e.type == EventType::Release && std::abs(e.frame - put_on_tray->frame) <= 2)
        return (e.poses[sugar].translation() - put_on_tray->poses[sugar].translation()).norm();
    return 1e9;
  };
  const auto sees_next_grasp = [&](const Demonstration& d) {
    const ContactEvent* g = event_after(d, "YCBV_03", EventType::Grasp, 80);
    return g && std::abs(g->frame - next_grasp->frame) <= 2;
  };
  const Demonstration rechecked = video.extract();
  ModelTrackerOptions as_tracked;
  as_tracked.rest_recheck = false;
  const Demonstration tracked = video.extract(as_tracked);
  EXPECT_LT(rest_error(rechecked), 0.01);
  EXPECT_GT(rest_error(tracked), 0.1) << "the rest stood on the tray as tracked: the test shows nothing";
  EXPECT_TRUE(sees_next_grasp(rechecked));
  EXPECT_FALSE(sees_next_grasp(tracked));
  EXPECT_GE(evaluate_demonstration(rechecked, truth, 2).matched, evaluate_demonstration(tracked, truth, 2).matched + 3);
}

// waiter_0 with the occluder: the cracker box, lifted off the tray (78) and carried fast behind
// the pole to the shelf's top (88), is lost there and shows again 4.6 of its radii from where it
// was last seen, on another face than it rested on: beyond every reach of the rest search. It
// is found where its colours show (global_search), its print bearing it out, and its carry's
// two events are found with it; without, it is lost for good.
TEST(ModelTracker, APartCarriedFarWhileLostIsFoundWhereItsColoursShow) {
  const TaskVideo video("global", [](SynthOptions& o) { o.occlusion = true; });
  const Demonstration truth = load_demonstration(video.s.truth);
  const ContactEvent* lifted = event_after(truth, "YCBV_02", EventType::Grasp, 70);
  const ContactEvent* put_on_shelf = release_after(truth, "YCBV_02", 70);
  ASSERT_TRUE(lifted && put_on_shelf);
  const auto cracker = static_cast<size_t>(put_on_shelf->object);
  auto near = [](const ContactEvent* e, const ContactEvent* t) { return e && std::abs(e->frame - t->frame) <= 2; };
  const ExtractionResult result = video.extraction();
  const Demonstration& found = result.demonstration;
  // The operator is told where to check.
  const auto told = std::find_if(result.warnings.begin(), result.warnings.end(), [](const std::string& w) {
    return w.rfind("part 'YCBV_02', frame ", 0) == 0 && w.find("found again where its colours show") != std::string::npos;
  });
  EXPECT_NE(told, result.warnings.end());
  if (told != result.warnings.end()) std::printf("%s\n", told->c_str());
  const ContactEvent* release = release_after(found, "YCBV_02", 70);
  EXPECT_TRUE(near(event_after(found, "YCBV_02", EventType::Grasp, 70), lifted));
  ASSERT_TRUE(near(release, put_on_shelf));
  EXPECT_LT(1e3 * (release->poses[cracker].translation() - put_on_shelf->poses[cracker].translation()).norm(), 10.0);
  ModelTrackerOptions near_only;
  near_only.global_search = false;
  const Demonstration lost = video.extract(near_only);
  EXPECT_FALSE(near(release_after(lost, "YCBV_02", 70), put_on_shelf)) << "found without: the test shows nothing";
  EXPECT_GE(evaluate_demonstration(found, truth, 2).matched, evaluate_demonstration(lost, truth, 2).matched + 2);
}

// ur5_workbench without markers (seed 5): the bracket, carried in the hand, is tracked onto
// something that stays still (68) and rests there 12 cm above the table, in front of the
// flanged cylinder, whose lines it then hides; the cylinder, never measured again, misses its
// carry (105-150). A rest that floats so, and is found standing nowhere near in two rechecks in a
// row, is no rest: taken back, the bracket is lost there and found where it stands, and the
// cylinder is measured again and its carry found.
TEST(ModelTracker, ARestFloatingWhereNothingHoldsItIsTakenBack) {
  const fs::path dir = fs::temp_directory_path() / ("demoplan_model_tracker_float_" + std::to_string(::getpid()));
  CellSynthOptions c;
  c.render.data_dir = DEMOPLAN_DATA_DIR;
  c.render.seed = 5;
  c.render.part_markers = false;
  c.cell = (fs::path(DEMOPLAN_DATA_DIR) / ".." / "cells" / "ur5_workbench.json").string();
  const CellSynthOutput s = write_synthetic_cell_demonstration(c, dir.string());
  const MarkerScene scene = load_marker_scene(s.scene);
  ExtractionOptions eo;
  eo.scene = marker_scene_world(scene, s.scene, DEMOPLAN_DATA_DIR);
  auto extract = [&](const ModelTrackerOptions& o) {
    auto tracker = make_model_tracker(scene, s.scene, DEMOPLAN_DATA_DIR, load_tracker_init(s.init), s.init, o);
    return extract_demonstration(s.video, load_camera(s.camera), *tracker, scene.task, eo);
  };
  const Demonstration truth = load_demonstration(s.truth);
  const ContactEvent* taken = event_after(truth, "flanged_cylinder", EventType::Grasp);
  const ContactEvent* put = release_after(truth, "flanged_cylinder");
  ASSERT_TRUE(taken && put);
  auto carried = [&](const Demonstration& d) {
    const ContactEvent* g = event_after(d, "flanged_cylinder", EventType::Grasp, taken->frame - 3);
    const ContactEvent* r = release_after(d, "flanged_cylinder", taken->frame - 3);
    return g && r && std::abs(g->frame - taken->frame) <= 2 && std::abs(r->frame - put->frame) <= 2;
  };
  const ExtractionResult taken_back = extract({});
  ModelTrackerOptions kept;
  kept.rest_recheck_unplaced = false;
  const ExtractionResult floating = extract(kept);
  fs::remove_all(dir);
  EXPECT_TRUE(carried(taken_back.demonstration));
  EXPECT_FALSE(carried(floating.demonstration)) << "found with the floating rest: the test shows nothing";
  EXPECT_GE(evaluate_demonstration(taken_back.demonstration, truth, 2).matched,
            evaluate_demonstration(floating.demonstration, truth, 2).matched + 3);
  // The operator is told.
  const auto told = std::find_if(taken_back.warnings.begin(), taken_back.warnings.end(), [](const std::string& w) {
    return w.rfind("part 'bracket', frames ", 0) == 0 && w.find("standing nowhere near") != std::string::npos;
  });
  ASSERT_NE(told, taken_back.warnings.end());
  std::printf("%s\n", told->c_str());
}

// waiter_0 in changing light: the sugar box, carried to the shelf behind the hand and lost
// there (102), is set down in front of the cracker box. Lost in its carry it still passes in
// front of the cracker box, which stays at its rest (lost_mover_frames; measured, the hand and
// the box it carries would drag it 19-72 mm off); and found standing level on the shelf, the
// sugar box is taken though its rest on the tray was tracked 13 degrees off level
// (rest_tilt_from_level; else its release is dated at 112, truth 104).
TEST(ModelTracker, APartSetDownInFrontOfAnotherWhileHidden) {
  const TaskVideo video("front", [](SynthOptions& o) { o.lighting = 0.3; });
  const Demonstration truth = load_demonstration(video.s.truth);
  const ContactEvent* set_down = release_after(truth, "YCBV_03", 95);
  ASSERT_TRUE(set_down);
  const auto cracker = static_cast<size_t>(std::find(truth.object_ids.begin(), truth.object_ids.end(), "YCBV_02") - truth.object_ids.begin());
  ASSERT_LT(cracker, truth.object_ids.size());
  // The sugar box's release within 2 frames and its pose there, and the cracker box's then (mm).
  struct Outcome {
    bool dated = false;
    double sugar_mm = 1e9, cracker_mm = 1e9;
  };
  auto outcome = [&](const Demonstration& d) {
    Outcome o;
    const ContactEvent* e = release_after(d, "YCBV_03", 95);
    if (!e) return o;
    o.dated = std::abs(e->frame - set_down->frame) <= 2;
    const auto sugar = static_cast<size_t>(set_down->object);
    o.sugar_mm = 1e3 * (e->poses[sugar].translation() - set_down->poses[sugar].translation()).norm();
    o.cracker_mm = 1e3 * (e->poses[cracker].translation() - set_down->poses[cracker].translation()).norm();
    return o;
  };
  const Outcome both = outcome(video.extract());
  EXPECT_TRUE(both.dated);
  EXPECT_LT(both.sugar_mm, 5.0);
  EXPECT_LT(both.cracker_mm, 5.0);
  // (Without the rest recheck: it finds a rest dragged off its support where it stands, and the
  // sugar box's rest on the tray standing level.)
  ModelTrackerOptions measured;
  measured.lost_mover_frames = 0;
  measured.rest_recheck = false;
  EXPECT_GT(outcome(video.extract(measured)).cracker_mm, 10.0);
  ModelTrackerOptions last_rest_only;
  last_rest_only.rest_tilt_from_level = false;
  last_rest_only.rest_recheck = false;
  EXPECT_FALSE(outcome(video.extract(last_rest_only)).dated);
}

// A part tracked within 3 mm in frames 0-9, never reported under the board in frames 10-19:
// the first frame from 20 on it is reported in again (-1: none).
int found_after_the_board(const PoseTracks& tracks, const std::vector<Pose>& truth) {
  EXPECT_EQ(tracks.frames, static_cast<int>(truth.size()));
  for (int f = 0; f < 10; ++f) {
    EXPECT_TRUE(tracks.samples[0][f].valid) << "frame " << f;
    if (tracks.samples[0][f].valid) {
      EXPECT_LT(error_mm(tracks.samples[0][f], truth[f]), 3.0) << "frame " << f;
    }
  }
  for (int f = 10; f < 20; ++f) EXPECT_FALSE(tracks.samples[0][f].valid) << "frame " << f << " was seen under the board";
  for (int f = 20; f < tracks.frames; ++f)
    if (tracks.samples[0][f].valid) return f;
  return -1;
}

// Hidden for 10 frames (a board right before the camera) while it is moved 8 cm: found again
// where it now is, and never reported seen elsewhere meanwhile.
TEST(ModelTracker, FindsAPartAgainAfterTenFramesFullyHidden) {
  std::vector<Pose> truth;
  std::vector<bool> covered;
  for (int f = 0; f < 36; ++f) {
    const double moved = std::clamp((f - 10) / 9.0, 0.0, 1.0) * 0.08;
    truth.push_back(box_pose(-0.04 + moved, 0.0, 0.9));
    covered.push_back(f >= 10 && f < 20);
  }
  const Clip clip = render_clip(truth, covered);
  const PoseTracks tracks = track_clip(clip, truth[0]);
  const int found = found_after_the_board(tracks, truth);
  ASSERT_GE(found, 20) << "never found again";
  EXPECT_LE(found, 22);
  for (int f = found; f < 36; ++f) {
    ASSERT_TRUE(tracks.samples[0][f].valid) << "frame " << f;
    EXPECT_LT(error_mm(tracks.samples[0][f], truth[f]), 5.0) << "frame " << f;
  }
}

// Carried 34 cm across and 10 cm away while a board hides it, farther than any search looks:
// lost for good, until the operator places it again (a correction in frame 25). From there it
// is tracked where it is, and the frames since the board left, which show it there already,
// are reported there too. Placed some centimetres off, it is moved onto the part there, as a
// start is.
TEST(ModelTracker, APartPlacedAgainByTheOperatorIsTrackedFromThere) {
  std::vector<Pose> truth;
  std::vector<bool> covered;
  for (int f = 0; f < 36; ++f) {
    const double moved = std::clamp((f - 10) / 9.0, 0.0, 1.0);
    truth.push_back(box_pose(-0.17 + 0.34 * moved, 0.0, 0.9 + 0.1 * moved));
    covered.push_back(f >= 10 && f < 20);
  }
  const Clip clip = render_clip(truth, covered);
  const PoseTracks lost = track_clip(clip, truth[0]);
  for (int f = 20; f < 36; ++f)
    EXPECT_TRUE(!lost.samples[0][f].valid || error_mm(lost.samples[0][f], truth[f]) > 20.0)
        << "frame " << f << ": found without the correction (the test needs a part lost for good)";
  const PoseTracks placed = track_clip(clip, truth[0], {}, {{"box", 25, truth[25]}});
  for (int f = 20; f < 36; ++f) {
    ASSERT_TRUE(placed.samples[0][f].valid) << "frame " << f;
    EXPECT_LT(error_mm(placed.samples[0][f], truth[f]), 5.0) << "frame " << f;
  }
  for (int f = 10; f < 19; ++f) EXPECT_FALSE(placed.samples[0][f].valid) << "frame " << f << " was seen under the board";
  // Placed by hand, 2.8 cm off across the view and 4 cm in depth (what an outline shows least):
  // moved onto the part in that frame, as a start is (taken as placed, frames 25-35 stay more
  // than 5 mm off).
  Pose rough = truth[25];
  rough.translation() += Eigen::Vector3d(0.02, -0.02, 0.04);
  const PoseTracks settled = track_clip(clip, truth[0], {}, {{"box", 25, rough}});
  for (int f = 25; f < 36; ++f) {
    ASSERT_TRUE(settled.samples[0][f].valid) << "frame " << f;
    EXPECT_LT(error_mm(settled.samples[0][f], truth[f]), 5.0) << "frame " << f;
  }
}

// Carried out of the picture and brought back in (30 frames out): not reported while out,
// found again once back, where it is.
TEST(ModelTracker, FindsAPartThatLeftThePictureOnceItIsBack) {
  std::vector<Pose> truth;
  for (int f = 0; f < 60; ++f) {
    // Out to the right (x 0.45 m: the whole box beyond the image's edge at 0.36 m), back to a
    // place 6 cm from where it left.
    const double out = f < 10 ? 0.0 : f < 20 ? (f - 10) / 10.0 : f < 40 ? 1.0 : f < 50 ? 1.0 - (f - 40) / 10.0 * 0.85 : 0.15;
    truth.push_back(box_pose(-0.05 + out * 0.5, 0.0, 0.9));
  }
  const Clip clip = render_clip(truth, std::vector<bool>(truth.size(), false));
  const PoseTracks tracks = track_clip(clip, truth[0]);
  for (int f = 22; f < 40; ++f) EXPECT_FALSE(tracks.samples[0][f].valid) << "frame " << f << " was seen out of the picture";
  for (int f = 52; f < 60; ++f) {
    ASSERT_TRUE(tracks.samples[0][f].valid) << "frame " << f;
    EXPECT_LT(error_mm(tracks.samples[0][f], truth[f]), 5.0) << "frame " << f;
  }
}

// The light changes while the box is moved (brighter and darker by 30 %, warmer and cooler by 15 %):
// followed all along, as each frame is brought back to the start frame's light.
TEST(ModelTracker, FollowsThroughAChangingLight) {
  std::vector<Pose> truth;
  for (int f = 0; f < 40; ++f) truth.push_back(box_pose(-0.06 + 0.12 * std::clamp((f - 5) / 30.0, 0.0, 1.0), 0.0, 0.9));
  Clip clip = render_clip(truth, std::vector<bool>(truth.size(), false));
  cv::RNG rng(7);
  for (size_t f = 0; f < clip.frames.size(); ++f) {
    // (With a little sensor noise, as in any video: the flawless render's few colours alone
    // would leave neighbouring colour bins unlearnt.)
    Degradation d;
    d.light = lighting_at(static_cast<int>(f), static_cast<int>(clip.frames.size()), 0.3);
    d.noise_sigma = 2.0;
    degrade(clip.frames[f], d, rng);
  }
  const PoseTracks tracks = track_clip(clip, truth[0]);
  for (int f = 0; f < 40; ++f) {
    ASSERT_TRUE(tracks.samples[0][f].valid) << "frame " << f;
    EXPECT_LT(error_mm(tracks.samples[0][f], truth[f]), 5.0) << "frame " << f;
  }
}

// Started 5 cm from where the part is (an operator's rough placement): put right within 10
// frames (here in the start frame already, segmented there), never followed confidently at the
// wrong place.
TEST(ModelTracker, AStartFiveCentimetresOffIsCorrected) {
  for (const Eigen::Vector3d& off : {Eigen::Vector3d(0.05, 0, 0), Eigen::Vector3d(0.03, 0.04, 0), Eigen::Vector3d(-0.035, 0.0, 0.035)}) {
    std::vector<Pose> truth;
    for (int f = 0; f < 20; ++f) truth.push_back(box_pose(0.0, 0.0, 0.9));
    const Clip clip = render_clip(truth, std::vector<bool>(truth.size(), false));
    Pose start = truth[0];
    start.translation() += off;
    const PoseTracks tracks = track_clip(clip, start);
    for (int f = 0; f < 20; ++f) {
      const PoseSample& s = tracks.samples[0][f];
      EXPECT_FALSE(s.valid && s.confidence >= 0.5 && error_mm(s, truth[f]) > 10.0)
          << "start off by " << off.transpose() << ": frame " << f << " tracked " << error_mm(s, truth[f])
          << " mm off with confidence " << s.confidence;
      if (f >= 10) {
        ASSERT_TRUE(s.valid) << "start off by " << off.transpose() << ": frame " << f;
        EXPECT_LT(error_mm(s, truth[f]), 5.0) << "start off by " << off.transpose() << ": frame " << f;
      }
    }
  }
}

// The demonstrator's hand over a part in the start frame (here a skin-coloured card over part
// of the box): the start is not what the frame shows there, and the operator is told, naming
// the start file, the part and the frame. A start in full view is not warned about.
TEST(ModelTracker, WarnsOfAStartSomethingNotModelledCovers) {
  const Pose box = box_pose(0.0, 0.0, 0.9);
  const Clip clear = render_clip({box}, {false});
  Clip covered = clear;
  Rasterizer r(clear.size, clear.K.fx, clear.K.fy, clear.K.cx, clear.K.cy, Pose::Identity());
  r.clear({180, 160, 150}, {120, 110, 100});
  r.draw(box_mesh(kBox, {40, 40, 200}), box);
  Pose card = Pose::Identity();
  card.translation() << 0.02, 0.0, 0.6;
  r.draw(box_mesh({0.04, 0.05, 0.005}, {150, 170, 210}), card);
  covered.frames[0] = r.color().clone();
  auto warnings = [](const Clip& clip) {
    TrackerInit init;
    init.parts.push_back({"box", clip.truth[0]});
    ModelTrackerOptions o;
    o.contour.views = 300;
    ModelPoseTracker tracker({{"box", true, box_mesh(kBox, {40, 40, 200})}}, init, "init.json", {}, o);
    tracker.start({clip.camera(), 30.0, 1});
    tracker.track(0, clip.frames[0]);
    tracker.finish();
    return tracker.warnings();
  };
  EXPECT_TRUE(warnings(clear).empty()) << warnings(clear).front();
  const std::vector<std::string> w = warnings(covered);
  ASSERT_EQ(w.size(), 1u);
  EXPECT_EQ(w[0].rfind("init.json: part 'box', frame 0: ", 0), 0u) << w[0];
  std::cout << w[0] << "\n";
}

// The starts are settled by GrabCut, which seeds its colour models from OpenCV's global random
// generator: whatever state an earlier computation left it in, a video tracks the same (the
// CLI's one extraction, the GUI's second and bench_extraction's twentieth agree; waiter_0 in
// changing light, extracted twice in one process, had 11 and then 6 of its 12 events right).
TEST(ModelTracker, TracksTheSameWhateverStateOpenCVsRandomGeneratorIsIn) {
  const TaskVideo video("rng", [](SynthOptions& o) { o.lighting = 0.3; });
  cv::VideoCapture capture(video.s.video);
  std::vector<cv::Mat> frames(4);
  for (auto& f : frames) ASSERT_TRUE(capture.read(f));
  auto track = [&](std::uint64_t seed) {
    cv::theRNG() = cv::RNG(seed);
    const auto tracker = video.tracker({});
    tracker->start({load_camera(video.s.camera), 30.0, static_cast<int>(frames.size())});
    for (size_t f = 0; f < frames.size(); ++f) tracker->track(static_cast<int>(f), frames[f]);
    return tracker->finish();
  };
  const PoseTracks first = track(1), second = track(987654321);
  ASSERT_EQ(first.samples.size(), second.samples.size());
  for (size_t k = 0; k < first.samples.size(); ++k)
    for (size_t f = 0; f < frames.size(); ++f) {
      EXPECT_EQ(first.samples[k][f].valid, second.samples[k][f].valid) << "part " << k << ", frame " << f;
      EXPECT_TRUE(first.samples[k][f].pose.isApprox(second.samples[k][f].pose, 0.0)) << "part " << k << ", frame " << f;
    }
}

// A table seen from above and in front, a wall standing on it: the box is carried while a board
// right before the camera hides everything (frames 10-19), and put down 22 cm away, turned by
// 20 degrees, 44 % of its outline behind the wall. At its last depth the search cannot reach it
// (nor accept it on half its outline); found on the table within 2 frames of the board
// leaving, where it is, and only with the search among the places it could rest (rest_search).
struct TableScene {
  Clip clip;
  std::vector<FurnitureMesh> furniture;
  Pose world_T_camera = Pose::Identity();
  RenderMesh box = box_mesh(kBox, {40, 40, 200});
};

Pose resting_box(double x, double y, double turn) {
  Pose p = Pose::Identity();
  p.linear() = Eigen::AngleAxisd(turn, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  p.translation() << x, y, kBox.z() / 2;  // standing on the table's top (z = 0)
  return p;
}

TableScene render_table_scene(const std::vector<Pose>& truth, const std::vector<bool>& covered,
                              const RenderMesh& box = box_mesh(kBox, {40, 40, 200})) {
  TableScene t;
  t.box = box;
  // The camera 0.6 m up, 0.6 m in front of the table's centre, looking down at it by 45 degrees.
  const Eigen::Vector3d forward = Eigen::Vector3d(0, 1, -1).normalized(), right(1, 0, 0);
  t.world_T_camera.linear().col(0) = right;
  t.world_T_camera.linear().col(1) = forward.cross(right);
  t.world_T_camera.linear().col(2) = forward;
  t.world_T_camera.translation() << 0, -0.6, 0.6;
  FurnitureMesh table{box_mesh({1.2, 1.2, 0.04}, {70, 100, 120}), Pose::Identity(), Pose::Identity(), "table",
                      Eigen::Vector3d(1.2, 1.2, 0.04)};
  table.world_T_mesh.translation() << 0, 0, -0.02;
  FurnitureMesh wall{box_mesh({0.3, 0.04, 0.3}, {150, 150, 150}), Pose::Identity(), Pose::Identity(), "",
                     Eigen::Vector3d(0.3, 0.04, 0.3)};
  wall.world_T_mesh.translation() << 0.25, -0.1, 0.15;  // its left edge at x = 0.10: half the box behind it
  t.furniture = {table, wall};
  t.clip.truth = truth;
  const RenderMesh board = box_mesh({0.4, 0.4, 0.01}, {128, 128, 128});
  Pose board_pose = Pose::Identity();
  board_pose.translation() << 0.0, 0.0, 0.3;
  for (size_t f = 0; f < truth.size(); ++f) {
    Rasterizer r(t.clip.size, t.clip.K.fx, t.clip.K.fy, t.clip.K.cx, t.clip.K.cy, t.world_T_camera);
    r.clear({180, 160, 150}, {120, 110, 100});
    for (const auto& m : t.furniture) r.draw(m.mesh, m.world_T_mesh);
    r.draw(box, truth[f]);
    if (covered[f]) r.draw(board, t.world_T_camera * board_pose);
    t.clip.frames.push_back(r.color().clone());
  }
  return t;
}

PoseTracks track_table_scene(const TableScene& t, ModelTrackerOptions o = {}) {
  TrackerInit init;
  init.parts.push_back({"box", t.clip.truth[0]});
  o.contour.views = 300;
  ModelPoseTracker tracker({{"box", true, t.box}}, init, "init.json", t.furniture, o);
  Camera c = t.clip.camera();
  c.world_T_camera = t.world_T_camera;
  tracker.start({c, 30.0, static_cast<int>(t.clip.frames.size())});
  for (size_t f = 0; f < t.clip.frames.size(); ++f) tracker.track(static_cast<int>(f), t.clip.frames[f]);
  return tracker.finish();
}

// Lifted 5 cm, carried 22 cm to the right and turned by `turn` while the board is up, set down
// at 18 (half behind the wall when turned little).
TableScene box_put_down_behind_a_wall(double turn = 0.35, const RenderMesh& box = box_mesh(kBox, {40, 40, 200})) {
  std::vector<Pose> truth;
  std::vector<bool> covered;
  for (int f = 0; f < 36; ++f) {
    const double s = std::clamp((f - 10) / 8.0, 0.0, 1.0);
    Pose p = resting_box(-0.12 + 0.22 * s, 0.0, turn * s);
    p.translation().z() += 0.05 * std::sin(M_PI * s);
    truth.push_back(p);
    covered.push_back(f >= 10 && f < 20);
  }
  return render_table_scene(truth, covered, box);
}

TEST(ModelTracker, FindsAPartPutDownHalfBehindAWall) {
  const TableScene scene = box_put_down_behind_a_wall();
  const std::vector<Pose>& truth = scene.clip.truth;
  const PoseTracks tracks = track_table_scene(scene);
  const int found = found_after_the_board(tracks, truth);
  ASSERT_GE(found, 20) << "never found again";
  EXPECT_LE(found, 22);
  // Reported where it is from then on. (Once at rest there, more than 40 % of its lines hidden,
  // it is held and no longer measured: rest_hidden_fraction.)
  int reported = 0;
  for (int f = found; f < 36; ++f) {
    if (!tracks.samples[0][f].valid) continue;
    ++reported;
    EXPECT_LT(error_mm(tracks.samples[0][f], truth[f]), 8.0) << "frame " << f;
    // (The plain box turned half round about the vertical looks the same.)
    const Eigen::Matrix3d error = truth[f].linear().transpose() * tracks.samples[0][f].pose.linear();
    const double turn = std::min(Eigen::AngleAxisd(error).angle(),
                                 Eigen::AngleAxisd(Eigen::AngleAxisd(M_PI, Eigen::Vector3d::UnitZ()) * error).angle());
    EXPECT_LT(turn * 180 / M_PI, 4.0) << "frame " << f;
  }
  EXPECT_GE(reported, 3);
  // Without the search among the places it could rest, it stays lost.
  ModelTrackerOptions without;
  without.rest_search = false;
  const PoseTracks lost = track_table_scene(scene, without);
  for (int f = 20; f < 36; ++f) EXPECT_FALSE(lost.samples[0][f].valid) << "frame " << f << " found without the rest search";
}

// The searches score their candidates on several threads: the tracks must not depend on how many.
TEST(ModelTracker, TracksTheSameOnOneSearchThreadOrThree) {
  const TableScene scene = box_put_down_behind_a_wall();
  ModelTrackerOptions one, three;
  one.search_threads = 1;
  three.search_threads = 3;
  const PoseTracks a = track_table_scene(scene, one), b = track_table_scene(scene, three);
  int found = 0;  // behind the wall, after the board: the rest search ran
  for (size_t f = 0; f < scene.clip.truth.size(); ++f) {
    ASSERT_EQ(a.samples[0][f].valid, b.samples[0][f].valid) << "frame " << f;
    if (!a.samples[0][f].valid) continue;
    found += f >= 20;
    EXPECT_TRUE(a.samples[0][f].pose.isApprox(b.samples[0][f].pose, 0.0)) << "frame " << f;
    EXPECT_EQ(a.samples[0][f].confidence, b.samples[0][f].confidence) << "frame " << f;
  }
  EXPECT_GE(found, 3);
}

// A box printed red at its -x end and blue at its +x end: turned half round about its vertical
// it shows the same outline and the other print.
RenderMesh two_tone_box() {
  RenderMesh m = box_mesh(kBox, {200, 200, 200});
  for (const auto& v : m.vertices) m.uvs.emplace_back(v.x() < 0 ? 0.1f : 0.9f, 0.5f);
  m.texture = cv::Mat(8, 64, CV_8UC3, cv::Scalar(40, 40, 200));
  m.texture(cv::Rect(32, 0, 32, 8)).setTo(cv::Scalar(200, 60, 40));
  return m;
}

Pose turned_half_round(const Pose& world_T_box) {
  Pose p = world_T_box;
  p.linear() = Eigen::AngleAxisd(M_PI, Eigen::Vector3d::UnitZ()).toRotationMatrix() * p.linear();
  return p;
}

double rotation_error_deg(const Pose& a, const Pose& b) {
  return Eigen::AngleAxisd(a.linear().transpose() * b.linear()).angle() * 180 / M_PI;
}

TEST(AppearanceError, TellsABoxFromTheBoxTurnedHalfRoundByItsPrint) {
  const RenderMesh box = two_tone_box();
  const TableScene scene = render_table_scene({resting_box(0.0, 0.0, 0.3)}, {false}, box);
  const Pose camera_T_box = scene.world_T_camera.inverse() * scene.clip.truth[0];
  const Pose camera_T_turned = scene.world_T_camera.inverse() * turned_half_round(scene.clip.truth[0]);
  const cv::Mat& frame = scene.clip.frames[0];
  const double right = appearance_error(frame, scene.clip.K, scene.world_T_camera, box, camera_T_box, {}, 0);
  const double turned = appearance_error(frame, scene.clip.K, scene.world_T_camera, box, camera_T_turned, {}, 0);
  EXPECT_LT(right, 5.0);
  EXPECT_GT(turned, 4 * right + 10.0);
  // In dimmer light (the drawing is scaled to the frame's colours) the same.
  const cv::Mat dim = frame * 0.6;
  EXPECT_LT(appearance_error(dim, scene.clip.K, scene.world_T_camera, box, camera_T_box, {}, 0), 5.0);
  EXPECT_GT(appearance_error(dim, scene.clip.K, scene.world_T_camera, box, camera_T_turned, {}, 0), 10.0);
  // Nothing of it shows: no answer.
  Pose behind = camera_T_box;
  behind.translation().z() = -1.0;
  EXPECT_LT(appearance_error(frame, scene.clip.K, scene.world_T_camera, box, behind, {}, 0), 0.0);
}

// The box put down turned half round (less 0.3 rad) while the board hides it: the rest search
// finds its outline, which alone has it turned the other way round; its print says which.
TEST(ModelTracker, APartFoundAtRestIsTurnedTheWayItsPrintShows) {
  const TableScene scene = box_put_down_behind_a_wall(M_PI - 0.3, two_tone_box());
  const PoseTracks tracks = track_table_scene(scene);
  ModelTrackerOptions outline_only;
  outline_only.rest_search_half_turn_ratio = 0;
  const PoseTracks by_outline = track_table_scene(scene, outline_only);
  int reported = 0, turned_by_outline = 0;
  for (int f = 20; f < 36; ++f) {
    if (by_outline.samples[0][f].valid && rotation_error_deg(by_outline.samples[0][f].pose, scene.clip.truth[f]) > 170) ++turned_by_outline;
    if (!tracks.samples[0][f].valid) continue;
    ++reported;
    EXPECT_LT(rotation_error_deg(tracks.samples[0][f].pose, scene.clip.truth[f]), 5.0) << "frame " << f;
    EXPECT_LT(error_mm(tracks.samples[0][f], scene.clip.truth[f]), 8.0) << "frame " << f;
  }
  // (Found at 20 and 21; then held, half behind the wall, unmeasured.)
  EXPECT_GE(reported, 2);
  EXPECT_GE(turned_by_outline, 2) << "the outline alone found it the right way round: the test shows nothing";
}

// Two boxes, one behind the other: the one in front hides the lower part of the one behind, and
// an arm (a skin-coloured bar, not tracked) reaches down over the box behind onto the front box,
// so the box behind learns the arm's colour as its own in the start frame. The arm takes the
// front box in frame 5 and carries it away to the left (frames 5-16) past the box behind, which
// stays. Listed first, the box behind is tracked before the front one in each frame; it must not
// be dragged along by the front box and the arm: held where it stands while the front box
// moves, and reported there once that is borne out (the front box at rest again), never moved.
TEST(ModelTracker, APartBehindIsHeldWhileTheOneInFrontIsCarriedPast) {
  const RenderMesh front = box_mesh(kBox, {40, 200, 220}), behind = box_mesh(kBox, {235, 235, 235});
  const RenderMesh arm = box_mesh({0.05, 0.4, 0.05}, {150, 180, 230});
  const Pose behind_pose = box_pose(0.03, -0.03, 1.0);
  std::vector<Pose> truth;
  Clip clip;
  for (int f = 0; f < 30; ++f) {
    const double s = std::clamp((f - 5) / 11.0, 0.0, 1.0);
    truth.push_back(box_pose(-0.18 * s, 0.06 - 0.03 * std::sin(M_PI * s), 0.85));
    Pose arm_pose = Pose::Identity();
    arm_pose.translation() = truth.back().translation() + Eigen::Vector3d(0.0, -0.25, 0.0);  // from above
    Rasterizer r(clip.size, clip.K.fx, clip.K.fy, clip.K.cx, clip.K.cy, Pose::Identity());
    r.clear({180, 160, 150}, {120, 110, 100});
    r.draw(behind, behind_pose);
    r.draw(front, truth.back());
    r.draw(arm, arm_pose);
    clip.frames.push_back(r.color().clone());
  }
  cv::RNG rng(3);
  for (auto& frame : clip.frames) {
    Degradation d;
    d.noise_sigma = 2.0;
    degrade(frame, d, rng);
  }
  TrackerInit init;
  init.parts.push_back({"behind", behind_pose});
  init.parts.push_back({"front", truth[0]});
  ModelTrackerOptions o;
  o.contour.views = 300;
  ModelPoseTracker tracker({{"behind", true, behind}, {"front", true, front}}, init, "init.json", {}, o);
  tracker.start({clip.camera(), 30.0, static_cast<int>(clip.frames.size())});
  for (size_t f = 0; f < clip.frames.size(); ++f) tracker.track(static_cast<int>(f), clip.frames[f]);
  const PoseTracks tracks = tracker.finish();
  for (int f = 0; f < 30; ++f) {
    const PoseSample& s = tracks.samples[0][f];
    if (f >= 5) {
      EXPECT_TRUE(s.valid && s.confidence >= 0.5) << "frame " << f << " not reported";
    }
    if (s.valid) {
      EXPECT_LT(error_mm(s, behind_pose), 5.0) << "frame " << f;
    }
  }
  // The front box followed to where it was put.
  ASSERT_TRUE(tracks.samples[1][29].valid);
  EXPECT_LT(error_mm(tracks.samples[1][29], truth[29]), 10.0);
}

// The ride's rules on their own: parts 1 and 2 rested 40 cm apart beside part 0 (unmeasured,
// at the origin); moved as one body (40 cm along x, turned by 0.5 rad about a point between
// them) they are a ride, and part 0's rest moved by its motion lands where the same turn and
// shift take it. Apart (one of them 20 cm off the body's motion), left at different times, not
// from beside it, or one alone: no ride.
TEST(RidePrediction, TwoPartsMovedAsOneBodyFromBesideAPartAreARide) {
  Pose M = Pose::Identity();
  M.linear() = Eigen::AngleAxisd(0.5, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  M.translation() << 0.4, 0.1, 0.0;
  std::vector<RidePart> parts(3);
  parts[0].rest = Eigen::Vector3d(0.0, 0.0, 0.85);
  parts[1].rest = Eigen::Vector3d(0.1, 0.2, 0.85);
  parts[2].rest = Eigen::Vector3d(0.5, 0.2, 0.86);
  for (int j = 1; j < 3; ++j) {
    parts[j].rest_bottom = 0.80;
    parts[j].left_rest = 10 + j;
    parts[j].tracked = true;
    parts[j].now = M * *parts[j].rest;
  }
  const RideRules rules;
  const std::optional<Ride> ride = Ride::detect(0, *parts[0].rest, 0.80, 0.05, parts, rules);
  ASSERT_TRUE(ride.has_value());
  EXPECT_EQ(ride->riders(), (std::vector<size_t>{1, 2}));
  const std::optional<Pose> motion = ride->motion(parts, rules);
  ASSERT_TRUE(motion.has_value());
  EXPECT_LT((*motion * *parts[0].rest - M * *parts[0].rest).norm(), 1e-9);
  // 20 cm out of the body's motion: parted, no motion.
  parts[2].now.x() += 0.2;
  EXPECT_TRUE(ride->parted(parts, rules));
  EXPECT_FALSE(ride->motion(parts, rules).has_value());
  EXPECT_FALSE(Ride::detect(0, *parts[0].rest, 0.80, 0.05, parts, rules).has_value());
  parts[2].now.x() -= 0.2;
  // Left their rests 10 frames apart: two carries, no ride.
  parts[2].left_rest = 21;
  EXPECT_FALSE(Ride::detect(0, *parts[0].rest, 0.80, 0.05, parts, rules).has_value());
  parts[2].left_rest = 12;
  // Neither rested beside part 0 (its lowest point 10 cm lower, both over 4 radii away).
  EXPECT_FALSE(Ride::detect(0, *parts[0].rest, 0.70, 0.05, parts, rules).has_value());
  // One alone is as often carried.
  parts[2].tracked = false;
  EXPECT_FALSE(Ride::detect(0, *parts[0].rest, 0.80, 0.05, parts, rules).has_value());
}

// Boxes standing on a board (no furniture: a tray) on the table, the first at its left end; a
// cover over the first (a hand resting on it) hides it in frames 6-25 while the board rides 28 cm
// to the right, turning by 17 degrees (frames 10-21).
struct BoardRide {
  static constexpr int kFrames = 34;
  TableScene t;
  std::vector<RenderMesh> boxes;
  RenderMesh board = box_mesh({0.34, 0.14, 0.02}, {60, 140, 170});
  std::vector<std::vector<Pose>> truth;  // per box, per frame
  std::vector<Pose> board_truth;         // the board's (its mesh's centre), per frame
};

BoardRide render_board_ride(int boxes) {
  BoardRide ride;
  const Eigen::Vector3d size(0.04, 0.06, 0.10);
  const std::vector<cv::Vec3f> colours = {{40, 40, 200}, {40, 200, 40}, {200, 60, 40}};
  const RenderMesh cover = box_mesh({0.12, 0.12, 0.01}, {150, 150, 150});
  // The boxes on the board (its top at z = 0.02), the left one first.
  std::vector<Pose> on_board;
  for (int k = 0; k < boxes; ++k) {
    const double x = -0.11 + 0.11 * k;
    ride.boxes.push_back(box_mesh(size, colours[static_cast<size_t>(k)]));
    Pose p = Pose::Identity();
    p.linear() = Eigen::AngleAxisd(0.3 + 2 * x, Eigen::Vector3d::UnitZ()).toRotationMatrix();
    p.translation() << x, 0.0, 0.02 + size.z() / 2;
    on_board.push_back(p);
  }
  auto board_at = [](int f) {
    const double s = std::clamp((f - 10) / 11.0, 0.0, 1.0), u = s * s * (3 - 2 * s);
    Pose b = Pose::Identity();
    b.linear() = Eigen::AngleAxisd(0.3 * u, Eigen::Vector3d::UnitZ()).toRotationMatrix();
    b.translation() << -0.14 + 0.28 * u, 0.0, 0.0;
    return b;
  };
  ride.t = render_table_scene({}, {});
  TableScene& t = ride.t;
  t.furniture.resize(1);  // the table only
  ride.truth.resize(static_cast<size_t>(boxes));
  for (int f = 0; f < BoardRide::kFrames; ++f) {
    Rasterizer r(t.clip.size, t.clip.K.fx, t.clip.K.fy, t.clip.K.cx, t.clip.K.cy, t.world_T_camera);
    r.clear({180, 160, 150}, {120, 110, 100});
    for (const auto& m : t.furniture) r.draw(m.mesh, m.world_T_mesh);
    ride.board_truth.push_back(board_at(f) * Pose(Eigen::Translation3d(0, 0, 0.01)));
    r.draw(ride.board, ride.board_truth.back());
    for (int k = 0; k < boxes; ++k) {
      ride.truth[k].push_back(board_at(f) * on_board[k]);
      r.draw(ride.boxes[k], ride.truth[k].back());
    }
    if (f >= 6 && f < 26) {
      // Over the left box, towards the camera.
      const Eigen::Vector3d c = ride.truth[0].back().translation();
      const Eigen::Vector3d towards = (t.world_T_camera.translation() - c).normalized();
      Pose p = t.world_T_camera;
      p.translation() = c + 0.08 * towards;
      r.draw(cover, p);
    }
    cv::Mat frame = r.color().clone();
    cv::RNG rng(11 + f);
    Degradation d;
    d.noise_sigma = 2.0;
    degrade(frame, d, rng);
    t.clip.frames.push_back(frame);
  }
  return ride;
}

// Three boxes stand on the board; the cover lifted in frame 26, the left box is 5 of its radii
// from where it was last seen, out of the search's reach, and 2 cm above the table, off the
// rest search's supports. The other two boxes rode as one body from beside it: it is looked
// for where the same ride took it, found there, and never reported at its old place meanwhile.
TEST(ModelTracker, APartHiddenOnABoardThatRidesIsFoundWhereTheRideTookIt) {
  const BoardRide ride = render_board_ride(3);
  const TableScene& t = ride.t;
  const auto& boxes = ride.boxes;
  const auto& truth = ride.truth;
  const int frames = BoardRide::kFrames;
  auto run = [&](const ModelTrackerOptions& options) {
    TrackerInit init;
    for (int k = 0; k < 3; ++k) init.parts.push_back({"box" + std::to_string(k), truth[k][0]});
    ModelTrackerOptions o = options;
    o.contour.views = 300;
    std::vector<ModelPart> parts;
    for (int k = 0; k < 3; ++k) parts.push_back({"box" + std::to_string(k), true, boxes[k]});
    ModelPoseTracker tracker(parts, init, "init.json", t.furniture, o);
    Camera c = t.clip.camera();
    c.world_T_camera = t.world_T_camera;
    tracker.start({c, 30.0, frames});
    for (int f = 0; f < frames; ++f) tracker.track(f, t.clip.frames[f]);
    return tracker.finish();
  };
  const PoseTracks tracks = run({});
  // The two in view followed all along.
  for (int k = 1; k < 3; ++k)
    for (int f = 0; f < frames; ++f) {
      ASSERT_TRUE(tracks.samples[k][f].valid) << "box " << k << ", frame " << f;
      EXPECT_LT(error_mm(tracks.samples[k][f], truth[k][f]), 15.0) << "box " << k << ", frame " << f;
    }
  // The covered one: never reported away from where it is, found within 3 frames of the cover
  // leaving and followed from there.
  int found = -1;
  for (int f = 0; f < frames; ++f) {
    const PoseSample& s = tracks.samples[0][f];
    if (!s.valid) continue;
    EXPECT_LT(error_mm(s, truth[0][f]), 15.0) << "frame " << f;
    if (f >= 26 && found < 0) found = f;
  }
  ASSERT_GE(found, 26) << "never found after the ride";
  EXPECT_LE(found, 28);
  for (int f = found; f < frames; ++f) EXPECT_TRUE(tracks.samples[0][f].valid) << "frame " << f;
  // Without the prediction, it stays lost. (The search where its colours show finds it in frame
  // 26 too, but knows only the furniture's supports: standing on the table under the board's
  // top, up to 29 mm off.)
  ModelTrackerOptions without;
  without.ride_prediction = false;
  without.global_search = false;
  const PoseTracks lost = run(without);
  for (int f = 26; f < frames; ++f) EXPECT_FALSE(lost.samples[0][f].valid) << "frame " << f << " found without the ride";
}

// One box on the board, the board tracked too (a tray), the ride not predicted: the covered box
// is lost while the board rides. Placed again by the operator once the cover is lifted, it rode
// the board: its frames since it was lost follow the board there, its rest before stays where it
// was, and no carry of its own is made of it.
TEST(ModelTracker, APartPlacedAgainOnABoardThatMovedRodeIt) {
  const BoardRide ride = render_board_ride(1);
  const int frames = BoardRide::kFrames, placed = 28;
  auto run = [&](const std::vector<PartCorrection>& corrections) {
    TrackerInit init;
    init.parts = {{"box", ride.truth[0][0]}, {"board", ride.board_truth[0]}};
    init.corrections = corrections;
    ModelTrackerOptions o;
    o.contour.views = 300;
    o.ride_prediction = false;
    ModelPoseTracker tracker({{"box", true, ride.boxes[0]}, {"board", false, ride.board}}, init, "init.json",
                             ride.t.furniture, o);
    Camera c = ride.t.clip.camera();
    c.world_T_camera = ride.t.world_T_camera;
    tracker.start({c, 30.0, frames});
    for (int f = 0; f < frames; ++f) tracker.track(f, ride.t.clip.frames[f]);
    return tracker.finish();
  };
  const PoseTracks lost = run({});
  double board_off = 0;  // how far the board's own track strays, which the ride's frames inherit
  for (int f = 0; f < frames; ++f) {
    ASSERT_TRUE(lost.samples[1][f].valid) << "the board, frame " << f;
    board_off = std::max(board_off, error_mm(lost.samples[1][f], ride.board_truth[f]));
  }
  EXPECT_LT(board_off, 15.0);
  int unseen = 0;
  for (int f = 10; f < 22; ++f) unseen += !lost.samples[0][f].valid;
  ASSERT_GE(unseen, 10) << "the test needs the box lost during the ride";
  const PoseTracks tracks = run({{"box", placed, ride.truth[0][placed]}});
  double ride_off = 0;
  for (int f = 0; f < frames; ++f) {
    const PoseSample& s = tracks.samples[0][f];
    if (f >= 10 && f <= placed) {
      EXPECT_TRUE(s.valid) << "frame " << f;
    }
    if (!s.valid) continue;
    // Where it was measured, as a part is; where it rode, as far off as the board's track twice
    // (where it is now and where it was then).
    EXPECT_LT(error_mm(s, ride.truth[0][f]), f >= 6 && f < placed ? 2 * board_off + 2.0 : 15.0) << "frame " << f;
    if (f >= 6 && f < placed) ride_off = std::max(ride_off, error_mm(s, ride.truth[0][f]));
  }
  std::printf("the board's track up to %.1f mm off; the box's ride up to %.1f mm\n", board_off, ride_off);
}

// A start that puts a part behind the camera or beside the picture is refused, naming the part.
TEST(ModelTracker, RefusesAStartOutsideTheImage) {
  const Clip clip = render_clip({box_pose(0, 0, 0.9)}, {false});
  // Starting the tracker on `init` is refused, naming the file, `field` and the part.
  auto refused = [&](const TrackerInit& init, const std::string& field) {
    ModelTrackerOptions o;
    o.contour.views = 20;
    ModelPoseTracker tracker({{"box", true, box_mesh(kBox, {40, 40, 200})}}, init, "init.json", {}, o);
    try {
      tracker.start({clip.camera(), 30.0, 1});
      ADD_FAILURE() << "accepted: " << field << " outside the image";
    } catch (const InputError& e) {
      EXPECT_EQ(e.file(), "init.json");
      EXPECT_EQ(e.field(), field);
      EXPECT_NE(e.reason().find("box"), std::string::npos) << e.what();
    }
  };
  for (const Pose& outside : {box_pose(0, 0, -0.5), box_pose(2.0, 0, 0.9)}) {
    TrackerInit init;
    init.parts.push_back({"box", outside});
    refused(init, "parts[0].world_T_object");
    // The same placement as a correction, the start right.
    init.parts[0].world_T_object = box_pose(0, 0, 0.9);
    init.corrections.push_back({"box", 5, outside});
    refused(init, "corrections[0].world_T_object");
  }
  // And a part without triangles, before any frame.
  TrackerInit init;
  init.parts.push_back({"empty", box_pose(0, 0, 0.9)});
  EXPECT_THROW(ModelPoseTracker({{"empty", true, RenderMesh{}}}, init, "init.json"), InputError);
}

}  // namespace
