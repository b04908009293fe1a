// The perception benchmark (docs/benchmarks.md, "Perception"): synthetic demonstration videos
// of every gtamp task, rendered clean, with noise and blur, and with a passing occluder, are
// extracted and compared with their ground truth (also from simulated BOP estimates and hand
// detections instead of markers); then the event detector runs on the real
// per-frame pose estimates of the tasks (objects_poses) against their contact labels.
// Prints Markdown tables. Usage: bench_extraction [--quick] [--segments] [--tracker model|ols|gos] [--keep DIR]
// (--tracker model: the videos without markers on the parts, the model-based tracker from init.json;
// ols, gos: the same videos and starts, OpenCV contrib's rapid trackers instead, for comparison)
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "bench/rapid_pose_tracker.h"
#include "core/demo/benchmark_demonstration.h"
#include "core/demo/benchmark_task.h"
#include "core/statistics.h"
#include "perception/camera/camera_model.h"
#include "perception/events/contact_detector.h"
#include "perception/events/demonstration_builder.h"
#include "perception/events/evaluation.h"
#include "perception/events/model_points.h"
#include "perception/extraction/extract_demonstration.h"
#include "perception/extraction/tracks_file.h"
#include "perception/markers/marker_scene.h"
#include "perception/render/part_meshes.h"
#include "perception/synthetic/synthetic_video.h"
#include "perception/tracking/contour_model_file.h"
#include "perception/tracking/marker_pose_tracker.h"
#include "perception/tracking/model_pose_tracker.h"
#include "perception/tracking/tracker_init.h"
#include "perception/tracking/pose_track.h"
#include "perception/tracking/track_error.h"

namespace fs = std::filesystem;
using namespace demoplan;
using namespace demoplan::perception;

namespace {

struct Condition {
  std::string name;
  double noise, blur;
  bool occlusion;
  bool hands;  // fuse the simulated hand-contact detections
  bool bop_only = false;  // no markers: the simulated BOP pose estimates (and the hands) only
  double lighting = 0.0;  // the light varies by this fraction over the video
};

struct Pool {
  int truth = 0, detected = 0, matched = 0;
  std::vector<double> timing, mm, deg, mssd;
  double frames = 0, seconds = 0;
  void add(const DemonstrationEvaluation& e) {
    truth += e.truth_events, detected += e.detected_events, matched += e.matched;
    timing.insert(timing.end(), e.timing_errors.begin(), e.timing_errors.end());
    mm.insert(mm.end(), e.translation_errors_mm.begin(), e.translation_errors_mm.end());
    deg.insert(deg.end(), e.rotation_errors_deg.begin(), e.rotation_errors_deg.end());
    mssd.insert(mssd.end(), e.mssd_errors_mm.begin(), e.mssd_errors_mm.end());
  }
};

void row(const std::string& label, const Pool& p, bool with_fps) {
  const double precision = p.detected ? double(p.matched) / p.detected : 0.0;
  const double recall = p.truth ? double(p.matched) / p.truth : 0.0;
  std::printf("| %s | %d | %d | %d | %.2f | %.2f | %.1f | %.2f | %.2f | %.2f | %.1f |", label.c_str(), p.truth, p.detected,
              p.matched, precision, recall, median(p.timing), median(p.mm), median(p.deg), median(p.mssd),
              p.mm.empty() ? 0.0 : *std::max_element(p.mm.begin(), p.mm.end()));
  if (with_fps) std::printf(" %.0f |", p.seconds > 0 ? p.frames / p.seconds : 0.0);
  std::printf("\n");
  std::fflush(stdout);
}

}  // namespace

int main(int argc, char** argv) {
  bool quick = false, segments = false;  // --segments: segment_tracks reads the tracks
  bool model = false;                     // --tracker model|ols|gos: videos without markers
  std::string tracker_name = "markers";
  std::string keep;
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--quick")) quick = true;
    if (!std::strcmp(argv[i], "--segments")) segments = true;
    if (!std::strcmp(argv[i], "--keep") && i + 1 < argc) keep = argv[++i];
    if (!std::strcmp(argv[i], "--tracker") && i + 1 < argc) tracker_name = argv[++i];
  }
  model = tracker_name != "markers";
  const std::string data = DEMOPLAN_DATA_DIR;
  const fs::path root = keep.empty() ? fs::temp_directory_path() / ("demoplan_bench_extraction_" + std::to_string(::getpid()))
                                     : fs::path(keep);
  const std::vector<std::string> tasks = quick ? std::vector<std::string>{"shelf_0"}
                                               : std::vector<std::string>{"shelf_0", "shelf_1", "shelf_2", "tunnel_0", "waiter_0"};
  // The contour models as the CLI keeps them: built on the first video of a part, read back after.
  ModelTrackerOptions model_options;
  model_options.contour_cache = (root / "contours").string();
  const std::vector<Condition> conditions =
      model ? std::vector<Condition>{{"clean", 0, 0, false, false},
                                     {"noise 6 + blur 3 px", 6, 3, false, false},
                                     {"occluder while carried", 0, 0, true, false},
                                     {"light 70-130 %", 0, 0, false, false, false, 0.3}}
            : std::vector<Condition>{{"clean", 0, 0, false, false},
                                     {"clean + hands", 0, 0, false, true},
                                     {"noise 6 + blur 3 px", 6, 3, false, false},
                                     {"noise 8 + blur 5 px", 8, 5, false, false},
                                     {"occluder while carried", 0, 0, true, false},
                                     {"no markers: simulated BOP poses + hands", 0, 0, false, true, true}};

  std::printf("## Synthetic videos (1280x720, 30 fps, %s; tolerance 2 frames)\n\n",
              !model ? "markers" : tracker_name == "model" ? "no markers, model-based tracker"
                                 : ("no markers, cv::rapid " + tracker_name + " tracker").c_str());
  std::printf("| task, condition | true events | detected | matched | precision | recall | median timing error (frames) "
              "| median translation error (mm) | median rotation error (deg) | median MSSD (mm) | max translation error (mm) "
              "| extraction fps |\n|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  // Every frame's error against synth's truth.tracks.json, per task and condition (printed after).
  std::vector<std::vector<TrackError>> every_frame(tasks.size(), std::vector<TrackError>(conditions.size()));
  for (const auto& c : conditions) {
    Pool all;
    for (const auto& t : tasks) {
      SynthOptions so;
      so.data_dir = data;
      so.task = t;
      so.robot = t == "waiter_0" ? "kmr_iiwa" : "panda";
      so.noise_sigma = c.noise;
      so.blur_px = c.blur;
      so.lighting = c.lighting;
      so.occlusion = c.occlusion;
      so.detections = c.hands;
      so.part_markers = !model;
      const fs::path dir = root / (t + "_" + std::to_string(&c - conditions.data()));
      const SynthOutput s = write_synthetic_demonstration(so, dir.string());
      ExtractionOptions eo;
      if (c.hands) eo.hands_json = s.hands;
      if (segments) eo.events = ExtractionOptions::Events::Segments;
      MarkerScene scene = load_marker_scene(s.scene);
      // The scene's supports, for the rests (counted in the extraction's time, as `extract` builds it too).
      const auto scene_start = std::chrono::steady_clock::now();
      eo.scene = marker_scene_world(scene, s.scene, data);
      const double scene_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - scene_start).count();
      if (c.bop_only) {
        for (auto& o : scene.objects) o.markers.clear();
        eo.bop_csv = s.bop_csv;
      }
      std::unique_ptr<PoseTracker> tracker;
      if (tracker_name == "ols" || tracker_name == "gos") {
        std::vector<RenderMesh> meshes = marker_scene_part_meshes(scene, s.scene, data);
        std::vector<std::pair<std::string, RenderMesh>> parts;
        // The baselines follow the planning parts only (not waiter_0's tray), as they were measured.
        for (size_t k = 0; k < scene.objects.size(); ++k)
          if (scene.objects[k].planning) parts.emplace_back(scene.objects[k].id, std::move(meshes[k]));
        tracker = std::make_unique<bench::RapidPoseTracker>(
            tracker_name == "ols" ? bench::RapidPoseTracker::Kind::Ols : bench::RapidPoseTracker::Kind::Gos, parts,
            load_tracker_init(s.init));
      } else if (model)
        tracker = make_model_tracker(scene, s.scene, data, load_tracker_init(s.init), s.init, model_options);
      else tracker = std::make_unique<MarkerPoseTracker>(scene);
      const ExtractionResult r = extract_demonstration(s.video, load_camera(s.camera), *tracker, scene.task, eo);
      const Demonstration truth = load_demonstration(s.truth);
      const DemonstrationEvaluation e = evaluate_demonstration(r.demonstration, truth, 2, benchmark_model_points(data, t));
      Pool one;
      one.add(e);
      one.frames = r.frames, one.seconds = r.seconds + scene_seconds;
      all.add(e);
      all.frames += r.frames, all.seconds += r.seconds + scene_seconds;
      row(t + ", " + c.name, one, true);
      every_frame[&t - tasks.data()][&c - conditions.data()] = track_error(r.raw, load_tracks_file(s.truth_tracks).raw);
    }
    row("**all, " + c.name + "**", all, true);
  }
  std::printf("\n## Every frame: the part frame's error (mm), median / 95th percentile, and the share of true "
              "part poses estimated\n\n| task |");
  for (const auto& c : conditions) std::printf(" %s |", c.name.c_str());
  std::printf("\n|---|");
  for (size_t i = 0; i < conditions.size(); ++i) std::printf("---|");
  std::printf("\n");
  for (size_t i = 0; i < tasks.size(); ++i) {
    std::printf("| %s |", tasks[i].c_str());
    for (const TrackError& e : every_frame[i])
      std::printf(" %.1f / %.1f, %.2f |", e.median_translation_mm, e.p95_translation_mm, e.coverage);
    std::printf("\n");
  }
  std::fflush(stdout);

  if (model) {
    if (keep.empty()) fs::remove_all(root);
    return 0;
  }
  std::printf("\n## Real pose tracks (gtamp objects_poses) against the contact labels\n\n");
  std::printf("| task | true events | detected | matched (2 frames) | precision | recall | matched (5 frames) | precision | "
              "recall | median signed timing error (frames) |\n|---|---|---|---|---|---|---|---|---|---|\n");
  for (const auto& t : tasks) {
    const BenchmarkTask task = load_benchmark_task(data, t);
    const Demonstration truth = demonstration_from_subgoals(task);
    const PoseTracks tracks = tracks_from_benchmark(task);
    const ContactAnalysis contacts = detect_contacts(tracks);
    const Demonstration found = build_demonstration(tracks, contacts, task.name());
    const auto e2 = evaluate_demonstration(found, truth, 2), e5 = evaluate_demonstration(found, truth, 5);
    std::vector<double> signed_errors;
    for (const auto& m : e5.matches) signed_errors.push_back(m.timing_error);
    std::printf("| %s | %d | %d | %d | %.2f | %.2f | %d | %.2f | %.2f | %+.1f |\n", t.c_str(), e2.truth_events,
                e2.detected_events, e2.matched, e2.precision, e2.recall, e5.matched, e5.precision, e5.recall,
                median(signed_errors));
  }
  if (keep.empty()) fs::remove_all(root);
  return 0;
}
