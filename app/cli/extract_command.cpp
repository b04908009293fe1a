// demoplan-cli extract: grasp/release events and part poses from a demonstration video.
#include <filesystem>
#include <iostream>
#include <memory>

#include <nlohmann/json.hpp>

#include "app/cli/command.h"
#include "app/cli/video_commands.h"
#include "core/demo/demonstration.h"
#include "core/error.h"
#include "core/io/file_extension.h"
#include "perception/camera/camera_model.h"
#include "perception/extraction/extract_demonstration.h"
#include "perception/extraction/tracks_file.h"
#include "perception/extraction/tracks_overlay.h"
#include "perception/render/part_meshes.h"
#include "perception/markers/marker_scene.h"
#include "perception/tracking/contour_model_file.h"
#include "perception/tracking/marker_pose_tracker.h"
#include "perception/tracking/model_pose_tracker.h"
#include "perception/tracking/track_coverage.h"
#include "perception/importers/bop_csv.h"
#include "perception/tracking/tracker_init.h"
#include "perception/tracking/tracker_init_bop.h"

namespace demoplan::cli {

namespace {

struct ExtractCliOptions {
  std::string video, camera, scene, detections, hands, out, events = "thresholds";
  std::string tracker = "markers", init, data_dir, overlay;
  bool board = false;
  bool json = false;
};

// The model tracker's start: a demoplan-tracker-init file, or a pose estimator's BOP results
// CSV (by extension), whose poses are in the camera's frame.
bool is_bop_csv(const std::string& init) { return lowercase_extension(init) == ".csv"; }

perception::TrackerInit model_tracker_start(const std::string& init, const perception::MarkerScene& scene,
                                            const perception::Camera& camera, const std::string& camera_path) {
  if (!is_bop_csv(init)) return perception::load_tracker_init(init);
  if (!camera.world_T_camera)
    throw InputError(camera_path, "world_T_camera",
                     "a start from pose estimates (" + init + ") needs the camera's pose in the world in the camera file");
  std::vector<std::string> parts;
  for (const auto& object : scene.objects) parts.push_back(object.id);
  const perception::TrackerInit start =
      perception::tracker_init_from_bop(perception::load_bop_csv(init), parts, *camera.world_T_camera, init);
  std::cerr << "start from " << init << ": frame " << start.frame << ", each part's best estimate there\n";
  return start;
}

int run_extract(const ExtractCliOptions& o) {
  const perception::MarkerScene scene = perception::load_marker_scene(o.scene);
  std::string camera_path = o.camera;
  if (camera_path.empty()) {
    if (scene.camera.empty()) throw InputError(o.scene, "camera", "no camera file given (use --camera)");
    camera_path = (std::filesystem::path(o.scene).parent_path() / scene.camera).string();
  }
  perception::Camera camera = perception::load_camera(camera_path);
  if (!camera.world_T_camera && !camera.board) {
    // A camera file from `calibrate` holds intrinsics only: the board that gives the camera's
    // pose is the one the scene's own camera file describes.
    const std::filesystem::path scene_camera = std::filesystem::path(o.scene).parent_path() / scene.camera;
    if (!scene.camera.empty() && std::filesystem::is_regular_file(scene_camera))
      camera.board = perception::load_camera(scene_camera.string()).board;
    if (!camera.board)
      throw InputError(camera_path, "world_T_camera",
                       "the camera file gives neither the camera pose nor a board to find it from, and the scene's "
                       "camera file gives no board either");
  }
  perception::ExtractionOptions options;
  options.bop_csv = o.detections;
  options.hands_json = o.hands;
  options.board_extrinsics = o.board;
  if (o.events == "segments") options.events = perception::ExtractionOptions::Events::Segments;
  options.camera_source = camera_path;
  options.scene = perception::marker_scene_world(scene, o.scene, o.data_dir);  // rests put onto its supports
  std::unique_ptr<perception::PoseTracker> tracker;
  std::string init;  // the model tracker's start file
  if (o.tracker == "model") {
    // The parts' poses in the first frame: --init, else init.json beside the scene.
    init = o.init;
    if (init.empty()) init = (std::filesystem::path(o.scene).parent_path() / "init.json").string();
    if (!std::filesystem::is_regular_file(init))
      throw InputError(init, "", "the model tracker needs every part's pose in the first frame: no such file (use --init)");
    perception::ModelTrackerOptions model_options;
    model_options.contour_cache = perception::default_contour_cache_folder();
    tracker = perception::make_model_tracker(scene, o.scene, o.data_dir, model_tracker_start(init, scene, camera, camera_path),
                                             init, model_options);
  } else {
    tracker = std::make_unique<perception::MarkerPoseTracker>(scene);
  }
  const perception::ExtractionResult r = perception::extract_demonstration(o.video, camera, *tracker, scene.task, options);
  save_demonstration(o.out, r.demonstration);
  const std::string tracks = perception::tracks_path_for(o.out);
  perception::save_tracks_file(tracks, r);
  if (!o.overlay.empty()) {
    perception::Camera posed = camera;
    posed.world_T_camera = r.world_T_camera;
    perception::write_tracks_overlay(o.video, posed, r.raw, perception::marker_scene_part_meshes(scene, o.scene, o.data_dir),
                                     o.overlay);
  }
  const auto issues = validate(r.demonstration);

  const Demonstration& d = r.demonstration;
  std::cerr << "extracted " << d.events.size() << " events from " << o.video << " (" << r.frames << " frames, "
            << static_cast<int>(r.frames_per_second) << " frames/s, " << r.tracker << " tracker, camera pose from "
            << r.extrinsics_source << ")\n";
  for (const auto& e : d.events)
    std::cerr << "  frame " << e.frame << "  " << (e.type == EventType::Grasp ? "grasp  " : "release") << "  "
              << d.object_ids[e.object] << "  confidence " << e.confidence << "\n";
  // How much of each part's track the tracker measured, and where it did not see the part.
  std::vector<perception::TrackCoverage> coverage;
  for (size_t k = 0; k < r.raw.object_ids.size(); ++k) {
    coverage.push_back(perception::track_coverage(r.raw.samples[k]));
    std::cerr << "  " << r.raw.object_ids[k] << ": " << perception::describe_coverage(coverage.back()) << "\n";
    // Lost for good by the model tracker: the operator can place it again where the video shows it.
    if (const int lost = coverage.back().lost_for_good_from(); lost > 0 && !init.empty())
      std::cerr << "  " << r.raw.object_ids[k] << ": lost from frame " << lost
                << " on; where a later frame shows it, place it again there in "
                << (is_bop_csv(init) ? "the \"corrections\" of a demoplan-tracker-init file with the parts' starts"
                                     : init + "'s \"corrections\"")
                << " and extract again (docs/perception.md)\n";
  }
  for (const auto& w : r.warnings) std::cerr << "  warning: " << w << "\n";
  for (const auto& i : issues) std::cerr << "  issue: " << i.message << "\n";
  std::cerr << "  wrote " << o.out << " and " << tracks << (o.overlay.empty() ? "" : " and " + o.overlay) << "\n";
  if (o.json) {
    nlohmann::json events = nlohmann::json::array();
    for (const auto& e : d.events)
      events.push_back({{"frame", e.frame},
                        {"object", d.object_ids[e.object]},
                        {"type", e.type == EventType::Grasp ? "grasp" : "release"},
                        {"confidence", e.confidence}});
    nlohmann::json seen = nlohmann::json::array();
    for (size_t k = 0; k < coverage.size(); ++k)
      seen.push_back({{"object", r.raw.object_ids[k]},
                      {"frames", coverage[k].frames},
                      {"seen", coverage[k].seen},
                      {"unsure", coverage[k].unsure},
                      {"unseen", coverage[k].unseen}});
    nlohmann::json iss = nlohmann::json::array();
    for (const auto& i : issues) iss.push_back(i.message);
    std::cout << nlohmann::json{{"video", o.video},
                                {"frames", r.frames},
                                {"fps", d.fps},
                                {"events", events},
                                {"extraction_fps", r.frames_per_second},
                                {"extraction_time_s", r.seconds},
                                {"extrinsics", r.extrinsics_source},
                                {"tracker", r.tracker},
                                {"demonstration", o.out},
                                {"tracks", tracks},
                                {"coverage", seen},
                                {"warnings", r.warnings},
                                {"issues", iss}}
                     .dump()
              << std::endl;
  }
  return issues.empty() ? kOk : kFailed;
}

}  // namespace

Command register_extract_command(CLI::App& app) {
  auto o = std::make_shared<ExtractCliOptions>();
  CLI::App* sub = add_video_subcommand(app, "extract");
  sub->add_option("video", o->video, "the video (mp4, avi, mkv)")->required();
  sub->add_option("--scene", o->scene, "marker scene (demoplan-marker-scene JSON)")->required()->check(CLI::ExistingFile);
  sub->add_option("--camera", o->camera, "camera (demoplan-camera JSON or OpenCV YAML); default: the scene's")
      ->check(CLI::ExistingFile);
  sub->add_option("--detections", o->detections, "6D pose estimates, BOP results CSV")->check(CLI::ExistingFile);
  sub->add_option("--hands", o->hands, "hand-contact detections (100DOH, demoplan-hand-detections JSON)")
      ->check(CLI::ExistingFile);
  sub->add_option("--out", o->out, "demonstration to write (the tracks go beside it, <stem>.tracks.json)")->required();
  sub->add_option("--events", o->events,
                  "event detector: thresholds (for marker tracks) or segments (for noisier tracks, e.g. a BOP "
                  "detector's; docs/perception.md)")
      ->check(CLI::IsMember({"thresholds", "segments"}))
      ->capture_default_str();
  sub->add_option("--tracker", o->tracker,
                  "pose tracker: markers (ArUco markers on the parts) or model (the parts' meshes, no markers; "
                  "needs --init)")
      ->check(CLI::IsMember({"markers", "model"}))
      ->capture_default_str();
  sub->add_option("--init", o->init,
                  "with --tracker model: every part's pose in the first frame, and any corrections (parts placed again "
                  "later; demoplan-tracker-init JSON), or a pose estimator's BOP results CSV (.csv: the first frame "
                  "with an estimate of every part, each part's best there); default: init.json beside the scene");
  sub->add_option("--overlay", o->overlay,
                  "also write the video with each part's outline where its track puts it (green: seen, red: "
                  "not seen in that frame), e.g. overlay.mp4");
  sub->add_flag("--board-extrinsics", o->board, "find the camera pose from the board even if the camera file gives it");
  sub->add_flag("--json", o->json, "print one JSON object on stdout");
  add_data_dir_option(*sub, o->data_dir);
  return {sub, [o] { return run_extract(*o); }};
}

}  // namespace demoplan::cli
