#include "perception/extraction/extract_demonstration.h"

#include <algorithm>
#include <chrono>
#include <stdexcept>

#include "core/demo/settle_demonstration.h"
#include "core/geometry/box_faces.h"
#include "core/scene/support.h"
#include "core/error.h"
#include "perception/camera/board_extrinsics.h"
#include "perception/events/demonstration_builder.h"
#include "perception/events/track_smoothing.h"
#include "perception/extraction/carrier_rides.h"
#include "perception/importers/bop_csv.h"
#include "perception/importers/hand_detections.h"
#include "perception/tracking/bop_fusion.h"
#include "perception/tracking/carrier_top.h"
#include "perception/video/video_reader.h"

namespace demoplan::perception {

namespace {

// A tracker's tracks must have a row per part, in its order: the hand fusion and the
// demonstration builder index both alike.
void check_rows(const PoseTracks& tracks, const PoseTracker& tracker) {
  const auto& parts = tracker.parts();
  bool same = tracks.object_ids.size() == parts.size();
  for (size_t k = 0; same && k < parts.size(); ++k) same = tracks.object_ids[k] == parts[k].id;
  if (!same) throw std::logic_error("pose tracker '" + tracker.name() + "': its tracks are not in the order of its parts");
}

// The tops of the parts not planned for (trays) at each event's frame, where last seen then:
// the supports the planning parts resting on them are settled on. A carrier that rests on the
// furniture then is settled there first, as the parts are: its depth, from its image alone, is
// its weakest coordinate (waiter_0's tray 27 mm off along the line of sight after its ride), and
// the parts on it would take that error over. Elsewhere, after a ride, where the fit of its
// riders puts it (carrier_rides.h).
EventSupports carrier_tops(const PoseTracks& tracks, const std::vector<TrackedPart>& parts, const Demonstration& d,
                           const Scene& scene, const SnapOptions& snap, const std::vector<FittedRide>& rides = {}) {
  const auto furniture = furniture_support_polygons(scene);
  EventSupports tops(d.events.size());
  for (size_t k = 0; k < parts.size() && k < tracks.samples.size(); ++k) {
    if (parts[k].planning) continue;
    const auto faces = box_faces(parts[k].extent);
    const auto& samples = tracks.samples[k];
    for (size_t i = 0; i < d.events.size(); ++i) {
      int f = std::min(d.events[i].frame, static_cast<int>(samples.size()) - 1);
      while (f >= 0 && !samples[f].valid) --f;
      if (f < 0) continue;
      Pose pose = samples[f].pose;
      if (const auto settled = snap_to_support(faces, pose, furniture, snap)) pose = settled->pose;
      else
        for (const FittedRide& ride : rides)
          if (ride.carrier == k && d.events[i].frame >= ride.end && d.events[i].frame <= ride.until)
            pose = ride.carrier_after;
      if (auto top = carrier_top(parts[k].extent, pose)) tops[i].push_back(std::move(*top));
    }
  }
  return tops;
}

}  // namespace

ExtractionResult extract_demonstration(const std::string& video_path, const Camera& camera_in, PoseTracker& tracker,
                                       const std::string& task, const ExtractionOptions& o) {
  const auto t0 = std::chrono::steady_clock::now();
  ExtractionResult r;
  r.tracker = tracker.name();
  // Read the optional inputs first: bad input fails before the long part.
  const std::vector<BopDetection> bop = o.bop_csv.empty() ? std::vector<BopDetection>{} : load_bop_csv(o.bop_csv);
  const std::vector<HandFrame> hands = o.hands_json.empty() ? std::vector<HandFrame>{} : load_hand_detections(o.hands_json);
  VideoReader video(video_path, 4);
  if (video.size() != camera_in.image_size)
    throw InputError(video_path, "frame 0",
                     "frames are " + std::to_string(video.size().width) + "x" + std::to_string(video.size().height) +
                         " but the camera is calibrated for " + std::to_string(camera_in.image_size.width) + "x" +
                         std::to_string(camera_in.image_size.height));
  Camera camera = camera_in;

  // The camera's pose: from the file, else from the board in the first frames that show it.
  r.extrinsics_source = "file";
  if (o.board_extrinsics || !camera.world_T_camera) {
    const VideoBoardPose b = camera_pose_from_board_video(video, camera, o.camera_source, o.board_detector, o.board_frames);
    camera.world_T_camera = b.world_T_camera;
    r.extrinsics_source = "board (" + std::to_string(b.frames) + " frames)";
  }
  r.world_T_camera = *camera.world_T_camera;

  const int frames = video.frame_count();
  tracker.start({camera, video.fps(), frames});
  const bool decode = tracker.needs_images();
  for (int f = 0; f < frames; ++f) {
    if (o.cancel && o.cancel->load()) {
      r.cancelled = true;
      r.frames = f;
      return r;
    }
    tracker.track(f, decode ? video.frame(f) : cv::Mat());
    if (o.progress) o.progress(f + 1, frames);
  }
  r.raw = tracker.finish();
  for (const std::string& w : tracker.warnings()) r.warnings.push_back(w);
  check_rows(r.raw, tracker);
  r.raw.resize(frames);
  if (!bop.empty()) fuse_bop_detections(r.raw, bop, r.world_T_camera, o.bop_csv, o.bop_weight, &r.warnings);

  r.contacts = o.events == ExtractionOptions::Events::Segments ? segment_tracks(r.raw, o.segmentation).contacts(r.raw)
                                                                : detect_contacts(r.raw, o.contacts);
  if (!hands.empty()) {
    std::vector<Eigen::AlignedBox3d> bounds;
    for (const auto& part : tracker.parts()) bounds.push_back(part.extent);
    fuse_hand_contacts(r.contacts, hand_contact_runs(hands, r.raw, bounds, camera, o.hands), r.raw, o.hands);
  }
  r.demonstration = build_demonstration(r.raw, r.contacts, task, o.contacts, &r.warnings);
  if (o.scene) {
    SettleOptions settle = o.settle;
    settle.snap.viewpoint = r.world_T_camera.translation();
    const EventSupports trays = carrier_tops(r.raw, tracker.parts(), r.demonstration, *o.scene, settle.snap);
    Demonstration settled = settle_on_supports(*o.scene, r.demonstration, settle, trays);
    // The carriers' rides fitted to where their riders, settled before them, show after them.
    const auto rides = o.fit_rides ? fit_carrier_rides(r.raw, r.contacts, tracker.parts(), settled, *o.scene, settle.snap,
                                                       camera, o.ride, &r.warnings)
                                   : std::vector<FittedRide>{};
    if (!rides.empty()) {
      settled = settle_on_supports(*o.scene, r.demonstration, settle,
                                   carrier_tops(r.raw, tracker.parts(), r.demonstration, *o.scene, settle.snap, rides));
      move_riders(settled, rides);
    }
    r.demonstration = std::move(settled);
  }
  r.smoothed = smooth_tracks(r.raw, r.contacts, o.contacts);
  r.frames = frames;
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  r.frames_per_second = r.seconds > 0 ? frames / r.seconds : 0.0;
  return r;
}

}  // namespace demoplan::perception
