#include "perception/extraction/extract_demonstration.h"

#include <chrono>

#include "core/error.h"
#include "perception/camera/board_extrinsics.h"
#include "perception/events/demonstration_builder.h"
#include "perception/importers/bop_csv.h"
#include "perception/importers/hand_detections.h"
#include "perception/tracking/bop_fusion.h"
#include "perception/tracking/pose_average.h"
#include "perception/tracking/track_smoothing.h"
#include "perception/video/video_reader.h"

namespace demoplan::perception {

ExtractionResult extract_demonstration(const std::string& video_path, const Camera& camera_in, const MarkerScene& scene,
                                       const ExtractionOptions& o) {
  const auto t0 = std::chrono::steady_clock::now();
  ExtractionResult r;
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
  const MarkerDetector detector(scene.dictionary, o.detector);
  bool have_markers = false;
  for (const auto& obj : scene.objects) have_markers = have_markers || !obj.markers.empty();

  // The camera's pose: from the file, else from the board in the first frames that show it.
  r.extrinsics_source = "file";
  if (o.board_extrinsics || !camera.world_T_camera) {
    if (!camera.board)
      throw InputError(o.camera_source, "world_T_camera", "the camera file gives neither the camera's pose nor a board to find it");
    PoseList poses;
    for (int f = 0; f < video.frame_count() && static_cast<int>(poses.size()) < o.board_frames; ++f)
      if (const auto b = camera_pose_from_board(*camera.board, camera, detector.detect(video.frame(f)), 3))
        poses.push_back(b->world_T_camera);
    if (poses.empty())
      throw InputError(video_path, "board", "the board of the camera file is not seen (3 markers or more) in any frame");
    camera.world_T_camera = median_pose(poses);
    r.extrinsics_source = "board (" + std::to_string(poses.size()) + " frames)";
  }
  r.world_T_camera = *camera.world_T_camera;

  MarkerTracker tracker(scene, camera, video.fps(), o.tracker);
  const int frames = video.frame_count();
  for (int f = 0; f < frames; ++f) {
    if (o.cancel && o.cancel->load()) {
      r.cancelled = true;
      r.frames = f;
      return r;
    }
    if (have_markers) tracker.add_frame(f, detector.detect(video.frame(f)));
    if (o.progress) o.progress(f + 1, frames);
  }
  r.raw = tracker.finish();
  r.raw.resize(frames);
  if (!bop.empty()) fuse_bop_detections(r.raw, bop, r.world_T_camera, o.bop_csv, o.bop_weight, &r.warnings);

  r.contacts = detect_contacts(r.raw, o.contacts);
  if (!hands.empty()) {
    std::vector<Eigen::AlignedBox3d> bounds;
    for (const auto& obj : scene.objects) bounds.push_back(marker_extent(obj));
    fuse_hand_contacts(r.contacts, hand_contact_runs(hands, r.raw, bounds, camera, o.hands), r.raw, o.hands);
  }
  r.demonstration = build_demonstration(r.raw, r.contacts, scene.task, o.contacts, &r.warnings);
  r.smoothed = smooth_tracks(r.raw, r.contacts, o.contacts);
  r.frames = frames;
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  r.frames_per_second = r.seconds > 0 ? frames / r.seconds : 0.0;
  return r;
}

}  // namespace demoplan::perception
