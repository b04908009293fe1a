#include "ui/document/extraction_runner.h"

#include <memory>

#include "core/error.h"
#include "perception/camera/camera_model.h"
#include "perception/events/tracks_demonstration.h"
#include "perception/extraction/extract_demonstration.h"
#include "perception/markers/marker_scene.h"
#include "perception/tracking/contour_model_file.h"
#include "perception/tracking/marker_pose_tracker.h"
#include "perception/tracking/model_pose_tracker.h"

namespace demoplan::ui {

Demonstration reorder_objects(const Demonstration& demo, const std::vector<std::string>& ids, const std::string& source) {
  std::vector<int> from(ids.size(), -1);  // new index -> old index
  std::vector<int> to(demo.object_ids.size(), -1);
  for (size_t i = 0; i < ids.size(); ++i) {
    from[i] = demo.object_index(ids[i]);
    if (from[i] < 0) throw InputError(source, "objects", "the video's marker scene does not track the part " + ids[i]);
    to[from[i]] = int(i);
  }
  Demonstration out;
  out.task = demo.task;
  out.fps = demo.fps;
  out.object_ids = ids;
  for (const ContactEvent& e : demo.events) {
    if (e.object < 0 || to[e.object] < 0) continue;  // a part the scene does not plan for (a tray)
    ContactEvent n = e;
    n.object = to[e.object];
    n.poses.clear();
    n.pose_frames.clear();
    for (size_t i = 0; i < ids.size(); ++i) {
      n.poses.push_back(e.poses[from[i]]);
      if (!e.pose_frames.empty()) n.pose_frames.push_back(e.pose_frames[from[i]]);
    }
    out.events.push_back(std::move(n));
  }
  return out;
}

bool ExtractionRunner::start(ExtractionJob job) {
  return run([this, job = std::move(job)](const Post& post, const std::atomic<bool>& cancel) {
    auto outcome = std::make_shared<ExtractionOutcome>();
    try {
      const perception::MarkerScene scene = perception::load_marker_scene(job.markers);
      const perception::Camera camera = perception::load_camera(job.camera);
      perception::ExtractionOptions options;
      options.camera_source = job.camera;
      options.scene = job.scene;
      options.cancel = &cancel;
      int last_percent = -1;
      options.progress = [&](int done, int total) {
        const int percent = total > 0 ? done * 100 / total : 0;
        if (percent == last_percent) return;
        last_percent = percent;
        post([this, done, total] { emit progress(done, total); });
      };
      std::unique_ptr<perception::PoseTracker> tracker;
      if (job.model_tracker) {
        perception::ModelTrackerOptions model_options;
        model_options.contour_cache = perception::default_contour_cache_folder();
        tracker = perception::make_model_tracker(scene, job.markers, job.data_dir, job.init, job.init_source, model_options);
      } else {
        tracker = std::make_unique<perception::MarkerPoseTracker>(scene);
      }
      const perception::ExtractionResult r = perception::extract_demonstration(job.video, camera, *tracker, job.task, options);
      if (!r.cancelled) {
        outcome->demonstration = reorder_objects(r.demonstration, job.object_ids, job.markers);
        outcome->warnings = r.warnings;
        outcome->frames = r.frames;
        outcome->seconds = r.seconds;
        auto tracks = std::make_shared<perception::TracksDemonstration>();
        tracks->tracks = r.raw;
        tracks->segmentation = perception::segment_tracks(r.raw);  // (the panel shows the document's demonstration)
        outcome->tracks = std::move(tracks);
        outcome->tracker = r.tracker;
        outcome->ok = true;
      }
    } catch (const std::exception& e) {
      outcome->error = e.what();
    }
    post([this, outcome] {
      finish();
      emit finished(*outcome);
    });
  });
}

}  // namespace demoplan::ui
