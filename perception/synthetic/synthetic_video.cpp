#include "perception/synthetic/synthetic_video.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <map>
#include <optional>
#include <set>
#include <variant>

#include <opencv2/imgproc.hpp>

#include "core/cell/cell.h"
#include "core/cell/cell_picks.h"
#include "core/cell/cell_scene.h"
#include "core/demo/benchmark_scene.h"
#include "core/demo/benchmark_task.h"
#include "core/error.h"
#include "core/model/kinematics.h"
#include "core/model/robot_model.h"
#include "perception/camera/camera_model.h"
#include "perception/extraction/tracks_file.h"
#include "perception/importers/bop_csv.h"
#include "perception/importers/hand_detections.h"
#include "perception/markers/marker_scene.h"
#include "perception/render/part_meshes.h"
#include "perception/render/rasterizer.h"
#include "perception/synthetic/board_placement.h"
#include "perception/synthetic/board_video.h"
#include "perception/synthetic/camera_placement.h"
#include "perception/synthetic/demo_script.h"
#include "perception/synthetic/hand_model.h"
#include "perception/synthetic/image_degradation.h"
#include "perception/synthetic/marker_layout.h"
#include "perception/tracking/tracker_init.h"
#include "perception/video/video_writer.h"

namespace demoplan::perception {

namespace fs = std::filesystem;

namespace {

constexpr const char* kDictionary = "DICT_4X4_100";
// The tray the waiter's parts ride on: drawn as a flat box of this colour (BGR) and, without
// markers, given to the tracker as a part by that box (the task's tray model is a stand-in cube).
const cv::Vec3f kTrayBgr{60, 90, 120};
constexpr const char* kTrayId = "TRAY";

// The tray's box centre in frame f (the script keeps its top centre).
Pose tray_centre(const DemoScript& script, int f) {
  Pose T = *script.tray[f];
  T.translation() -= T.linear().col(2) * (script.tray_size.z() / 2);
  return T;
}

struct Placed {
  RenderMesh mesh;
  Pose pose;
};

struct Assets {
  std::vector<Placed> furniture;
  std::vector<Eigen::AlignedBox3d> obstacles;
  std::vector<RenderMesh> parts;  // planning objects, task order
  std::optional<Pose> table_top;
  Eigen::Vector2d table_size = Eigen::Vector2d::Zero();
  // A cell's places for the extrinsics board, tried in turn: upward box tops, largest first.
  std::vector<std::pair<Pose, Eigen::Vector2d>> board_tops;
};

Eigen::AlignedBox3d world_box(const FurnitureMesh& f) {
  Eigen::AlignedBox3d box;
  for (const auto& v : f.mesh.vertices) box.extend(f.world_T_mesh * v.cast<double>());
  return box;
}

Assets load_assets(const BenchmarkTask& task) {
  Assets a;
  MeshCache cache;
  double best_area = 0;
  for (auto& f : furniture_meshes(task)) {
    a.obstacles.push_back(world_box(f));
    if (f.box && f.kind == "table" && f.box->x() * f.box->y() > best_area) {
      best_area = f.box->x() * f.box->y();
      a.table_top = f.world_T_link;
      a.table_size = f.box->head<2>();
    }
    a.furniture.push_back({std::move(f.mesh), f.world_T_mesh});
  }
  UrdfOptions options;
  options.load_visual_meshes = true;
  options.mesh_cache = &cache;
  for (const auto& id : task.planning_object_ids) {
    const auto it = std::find_if(task.objects.begin(), task.objects.end(), [&](auto& o) { return o.id == id; });
    a.parts.push_back(part_render_mesh(load_urdf(it->urdf, options), it->urdf));
  }
  return a;
}

// The furniture and parts of a scene built with visual meshes (a cell's): every visual of every
// furniture link, the parts' visuals in their root link frame; the upward box tops are where the
// extrinsics board may go.
Assets scene_assets(const Scene& scene) {
  Assets a;
  for (auto& f : furniture_meshes(scene)) {
    a.obstacles.push_back(world_box(f));
    if (f.box && f.world_T_mesh.linear().col(2).z() > 0.99) {
      Pose top = f.world_T_mesh;
      top.translation() += top.linear().col(2) * (f.box->z() / 2);
      a.board_tops.push_back({top, f.box->head<2>()});
    }
    a.furniture.push_back({std::move(f.mesh), f.world_T_mesh});
  }
  for (const auto& o : scene.objects) a.parts.push_back(part_render_mesh(o.model, o.id));
  std::stable_sort(a.board_tops.begin(), a.board_tops.end(),
                   [](auto& x, auto& y) { return x.second.prod() > y.second.prod(); });
  return a;
}

std::vector<std::string> object_ids(const Scene& scene) {
  std::vector<std::string> ids;
  for (const auto& o : scene.objects) ids.push_back(o.id);
  return ids;
}

// A large floor of tiles, centred below `centre`.
RenderMesh floor_mesh(const Eigen::Vector3d& centre) {
  RenderMesh m;
  const float h = 6.0f, x = float(centre.x()), y = float(centre.y());
  m.vertices = {{x - h, y - h, 0.f}, {x + h, y - h, 0.f}, {x + h, y + h, 0.f}, {x - h, y + h, 0.f}};
  m.uvs = {{0.f, 0.f}, {1.f, 0.f}, {1.f, 1.f}, {0.f, 1.f}};
  m.triangles = {{0, 1, 2}, {0, 2, 3}};
  m.texture.create(768, 768, CV_8UC3);
  cv::RNG rng(12345);
  for (int r = 0; r < 24; ++r)
    for (int c = 0; c < 24; ++c) {
      const int g = 95 + ((r + c) % 2) * 20 + rng.uniform(-6, 7);
      m.texture(cv::Rect(c * 32, r * 32, 32, 32)).setTo(cv::Scalar(g + 4, g, g - 6));
    }
  return m;
}

// The marker images, one per id.
struct MarkerArt {
  std::string dictionary = kDictionary;
  std::map<int, cv::Mat> images;
  const cv::Mat& get(int id) {
    auto it = images.find(id);
    if (it == images.end()) it = images.emplace(id, marker_image(dictionary, id)).first;
    return it->second;
  }
};

Pose marker_frame_on_board(const std::vector<cv::Point3f>& c) {
  // Corners: top-left, top-right, bottom-right, bottom-left of the printed marker.
  Eigen::Vector3d p[4];
  for (int k = 0; k < 4; ++k) p[k] = {c[k].x, c[k].y, c[k].z};
  Pose T = Pose::Identity();
  const Eigen::Vector3d x = (p[1] - p[0]).normalized(), y = (p[0] - p[3]).normalized();
  T.linear().col(0) = x;
  T.linear().col(1) = y;
  T.linear().col(2) = x.cross(y);
  T.translation() = (p[0] + p[1] + p[2] + p[3]) / 4;
  return T;
}

// Pixel box of world points; empty when any is behind the camera.
cv::Rect2d pixel_box(const Rasterizer& r, const std::vector<Eigen::Vector3d>& points) {
  double x0 = 1e18, y0 = 1e18, x1 = -1e18, y1 = -1e18;
  for (const auto& p : points) {
    const auto q = r.project(p);
    if (!q) return {};
    x0 = std::min(x0, q->x()), y0 = std::min(y0, q->y()), x1 = std::max(x1, q->x()), y1 = std::max(y1, q->y());
  }
  return {x0, y0, x1 - x0, y1 - y0};
}

std::vector<Eigen::Vector3d> box_corners(const Eigen::AlignedBox3d& b, const Pose& pose) {
  std::vector<Eigen::Vector3d> out;
  for (int c = 0; c < 8; ++c) out.push_back(pose * b.corner(static_cast<Eigen::AlignedBox3d::CornerType>(c)));
  return out;
}

// The ArUco board that gives a synthetic video's camera extrinsics, ids first_id .. first_id + 5.
MarkerBoard extrinsics_board(int first_id, const std::string& dictionary = kDictionary) {
  MarkerBoard board;
  board.dictionary = dictionary;
  board.markers_x = 3;
  board.markers_y = 2;
  board.marker_length = 0.07;
  board.marker_separation = 0.015;
  board.first_id = first_id;
  return board;
}

// Renders the video of `script` (the hand added) as `camera` sees it and writes it with the
// camera, marker scene and truth files into `out_dir`.
SynthOutput render_demonstration(const SynthOptions& o, const std::string& out_dir, const Assets& assets,
                                 const DemoScript& script, const std::vector<Eigen::AlignedBox3d>& bounds,
                                 const Camera& camera, const MarkerScene& markers, const Demonstration& truth,
                                 std::chrono::steady_clock::time_point t0) {
  // The static part: floor, furniture, board.
  const Pose& world_T_camera = *camera.world_T_camera;
  Rasterizer r(camera.image_size, camera.fx, camera.fy, camera.cx, camera.cy, world_T_camera);
  r.clear({205, 190, 175}, {150, 140, 130});
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  for (const auto& p : script.poses.front()) centre += p.translation() / double(script.poses.front().size());
  r.draw(floor_mesh(centre), Pose::Identity());
  for (const auto& f : assets.furniture) r.draw(f.mesh, f.pose);
  MarkerArt art;
  art.dictionary = markers.dictionary;
  MarkerArt board_art;
  if (camera.board) {
    const MarkerBoard& b = *camera.board;
    const auto grid = b.make();
    Pose paper = b.world_T_board;
    Eigen::AlignedBox3d extent;
    for (const auto& m : grid->objPoints)
      for (const auto& c : m) extent.extend(Eigen::Vector3d(c.x, c.y, c.z));
    paper.translation() = b.world_T_board * Eigen::Vector3d(extent.center().x(), extent.center().y(), 0.0004);  // behind the markers
    r.draw(box_mesh({extent.sizes().x() + 0.04, extent.sizes().y() + 0.04, 0.0004}, {245, 245, 245}), paper);
    board_art.dictionary = b.dictionary;
    for (size_t i = 0; i < grid->objPoints.size(); ++i)
      r.draw_marker(board_art.get(grid->ids[i]), printed_marker_side(b.dictionary, b.marker_length),
                    b.world_T_board * marker_frame_on_board(grid->objPoints[i]));
  }
  const cv::Mat static_color = r.color().clone(), static_depth = r.depth().clone();

  const RenderMesh hand = hand_mesh();
  const RenderMesh tray = box_mesh(script.tray_size, kTrayBgr);
  const RenderMesh pole = cylinder_mesh(0.05, 0.8, {70, 60, 55});
  cv::RNG blur_rng(o.seed * 2654435761u + 17);
  Degradation degradation{o.noise_sigma, o.blur_px, blur_rng.uniform(0.0, M_PI)};

  SynthOutput out;
  out.fps = script.fps;
  out.frames = script.frames;
  // MP4 holds MPEG-4 and H.264; lossless FFV1 needs Matroska, MJPG goes in AVI.
  const std::string ext = o.fourcc == "FFV1" ? ".mkv" : o.fourcc == "MJPG" ? ".avi" : ".mp4";
  out.video = (fs::path(out_dir) / ("video" + ext)).string();
  out.camera = (fs::path(out_dir) / "camera.json").string();
  out.scene = (fs::path(out_dir) / "scene.json").string();
  out.truth = (fs::path(out_dir) / "truth.json").string();
  out.init = (fs::path(out_dir) / "init.json").string();
  VideoWriter writer(out.video, script.fps, camera.image_size, o.fourcc);
  std::vector<BopDetection> bop;
  std::vector<HandFrame> hands;
  cv::RNG detection_rng(o.seed * 7919u + 5);
  const Eigen::AlignedBox3d palm(Eigen::Vector3d(-0.05, -0.0425, -0.015), Eigen::Vector3d(0.05, 0.0425, 0.015));
  for (int f = 0; f < script.frames; ++f) {
    if (o.cancel && o.cancel->load()) {
      out.cancelled = true;
      return out;  // the writer removes its partial file
    }
    r.restore(static_color, static_depth);
    if (script.tray[f]) r.draw(tray, tray_centre(script, f));
    for (size_t k = 0; k < script.object_ids.size(); ++k) {
      const Pose& P = script.poses[f][k];
      r.draw(assets.parts[k], P);
      for (const auto& m : markers.objects[k].markers)
        r.draw_marker(art.get(m.id), printed_marker_side(markers.dictionary, m.size), P * m.object_T_marker);
    }
    r.draw(hand, script.hand[f]);
    if (o.occlusion)
      for (const auto& c : script.carries) {
        const int d = c.release - c.grasp, a = c.grasp + int(0.3 * d), b = c.grasp + int(0.7 * d);
        if (f < a || f > b || b <= a) continue;
        const int mid = (a + b) / 2;
        const Eigen::Vector3d part = script.poses[mid][c.object] * bounds[c.object].center();
        const Eigen::Vector3d eye = world_T_camera.translation();
        const double s = double(f - a) / (b - a);
        Pose T = Pose::Identity();
        T.translation() = part + 0.45 * (eye - part) + world_T_camera.linear().col(0) * (0.3 * (s - 0.5));
        r.draw(pole, T);
      }
    if (o.detections) {
      // A pose estimator sees every part whose centre is not hidden; a hand detector boxes the palm.
      for (size_t k = 0; k < script.object_ids.size(); ++k) {
        const Pose P = script.poses[f][k];
        const auto c = r.project(P * bounds[k].center());
        if (!c || c->x() < 0 || c->y() < 0 || c->x() >= camera.image_size.width || c->y() >= camera.image_size.height) continue;
        const double radius = bounds[k].sizes().norm() / 2;
        if (r.depth().at<float>(int(c->y()), int(c->x())) < c->z() - radius - 0.01) continue;
        BopDetection d;
        d.image_id = f;
        d.object_id = bop_object_id(script.object_ids[k]);
        d.score = 0.9;
        d.camera_T_object = world_T_camera.inverse() * P;
        const Eigen::Vector3d w(detection_rng.gaussian(0.01), detection_rng.gaussian(0.01), detection_rng.gaussian(0.01));
        d.camera_T_object.linear() = d.camera_T_object.linear() * Eigen::AngleAxisd(w.norm(), w.norm() > 0 ? w.normalized() : Eigen::Vector3d::UnitZ()).toRotationMatrix();
        d.camera_T_object.translation() += Eigen::Vector3d(detection_rng.gaussian(0.002), detection_rng.gaussian(0.002), detection_rng.gaussian(0.004));
        d.time = 0.05;
        bop.push_back(d);
      }
      HandFrame hf;
      hf.frame = f;
      HandDetection h;
      h.box = pixel_box(r, box_corners(palm, script.hand[f]));
      h.score = 0.95;
      for (const auto& c : script.carries)
        if (f >= c.grasp && f < c.release) {  // in contact: the grasp frame up to the release (excluded)
          const cv::Rect2d ob = pixel_box(r, box_corners(bounds[c.object], script.poses[f][c.object]));
          if (ob.area() <= 0) break;
          hf.objects.push_back({ob, 0.9});
          h.contact = HandContact::Portable;
          const double dx = ob.x + ob.width / 2 - (h.box.x + h.box.width / 2), dy = ob.y + ob.height / 2 - (h.box.y + h.box.height / 2);
          const double len = std::hypot(dx, dy);
          h.magnitude = len / 10000.0;
          h.dx = len > 0 ? dx / len : 0.0;
          h.dy = len > 0 ? dy / len : 0.0;
        }
      if (h.box.area() > 0) hf.hands.push_back(h);
      hands.push_back(hf);
    }
    cv::Mat frame = r.color().clone();
    cv::RNG noise_rng(o.seed * 1000003u + static_cast<unsigned>(f));
    degradation.light = lighting_at(f, script.frames, o.lighting);
    degrade(frame, degradation, noise_rng);
    writer.write(frame);
    if (o.progress) o.progress(f + 1, script.frames);
  }
  writer.finish();
  save_camera(out.camera, camera);
  save_marker_scene(out.scene, markers);
  save_demonstration(out.truth, truth);
  // Every part's true pose in every frame (and the tray's), as an extraction's tracks file: what
  // a tracker's per-frame estimates are compared with.
  ExtractionResult truth_tracks;
  PoseTracks& tracks = truth_tracks.raw;
  tracks.fps = script.fps;
  tracks.object_ids = script.object_ids;
  tracks.planning.assign(script.object_ids.size(), true);
  const bool has_tray = std::any_of(markers.objects.begin(), markers.objects.end(), [](const auto& m) { return m.id == kTrayId; });
  if (has_tray) {
    tracks.object_ids.push_back(kTrayId);
    tracks.planning.push_back(false);
  }
  tracks.resize(script.frames);
  for (int f = 0; f < script.frames; ++f)
    for (size_t k = 0; k < tracks.object_ids.size(); ++k) {
      PoseSample& s = tracks.samples[k][f];
      const bool part = k < script.object_ids.size();
      s.valid = part || script.tray[f].has_value();
      if (!s.valid) continue;
      s.pose = part ? script.poses[f][k] : tray_centre(script, f);
      s.confidence = 1.0;
    }
  truth_tracks.smoothed = tracks;
  truth_tracks.tracker = "truth";
  truth_tracks.extrinsics_source = "file";
  truth_tracks.world_T_camera = world_T_camera;
  truth_tracks.frames = script.frames;
  out.truth_tracks = tracks_path_for(out.truth);
  save_tracks_file(out.truth_tracks, truth_tracks);
  // Where a model-based tracker starts: the truth in frame 0.
  TrackerInit init;
  for (size_t k = 0; k < tracks.object_ids.size(); ++k)
    if (tracks.samples[k][0].valid) init.parts.push_back({tracks.object_ids[k], tracks.samples[k][0].pose});
  save_tracker_init(out.init, init);
  out.events = static_cast<int>(truth.events.size());
  if (o.detections) {
    out.bop_csv = (fs::path(out_dir) / "bop.csv").string();
    out.hands = (fs::path(out_dir) / "hands.json").string();
    save_bop_csv(out.bop_csv, bop);
    save_hand_detections(out.hands, hands);
  }
  out.render_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return out;
}

}  // namespace

SynthOutput write_synthetic_demonstration(const SynthOptions& o, const std::string& out_dir) {
  const auto t0 = std::chrono::steady_clock::now();
  const BenchmarkTask task = load_benchmark_task(o.data_dir, o.task);
  const auto pose_ids = benchmark_pose_ids(task, o.robot);
  if (std::find(pose_ids.begin(), pose_ids.end(), o.robot_pose) == pose_ids.end())
    throw InputError(task.file, "robot_poses", "task " + o.task + " has no pose " + std::to_string(o.robot_pose) +
                                                   " for robot '" + o.robot + "'");
  if (o.noise_sigma < 0 || o.blur_px < 0) throw InputError("synth options", "noise/blur", "must be >= 0");
  if (o.lighting < 0 || o.lighting >= 1) throw InputError("synth options", "lighting", "must be in [0, 1)");
  std::error_code ec;
  fs::create_directories(out_dir, ec);
  if (!fs::is_directory(out_dir)) throw InputError(out_dir, "", "cannot create the output folder");

  const Assets assets = load_assets(task);
  std::vector<Eigen::AlignedBox3d> bounds;
  for (const auto& p : assets.parts) bounds.push_back(p.bounds().cast<double>());
  DemoScript script = make_demo_script(task, bounds, o.time_scale);
  std::vector<std::vector<ObjectMarker>> part_markers;
  for (size_t k = 0; k < script.object_ids.size(); ++k)
    part_markers.push_back(box_face_markers(bounds[k], kBoxFaceMarkers * static_cast<int>(k)));
  Camera camera = place_camera(script, assets.obstacles, part_markers);
  if (!o.part_markers) part_markers.assign(part_markers.size(), {});
  add_hand(script, camera.world_T_camera->translation());
  if (o.board && assets.table_top) camera.board = place_board(script, *assets.table_top, assets.table_size, camera, assets.obstacles, extrinsics_board(90));

  MarkerScene markers;
  markers.task = task.name();
  markers.robot = o.robot;
  markers.robot_pose = o.robot_pose;
  markers.camera = "camera.json";
  markers.dictionary = kDictionary;
  for (size_t k = 0; k < script.object_ids.size(); ++k)
    markers.objects.push_back({script.object_ids[k], true, part_markers[k], std::nullopt});
  // Without markers the tray is followed as a part too, as the task's raw poses follow it: the
  // parts resting on it then rest on its top, whose height their images alone do not give.
  if (!o.part_markers && !script.tray.empty() && script.tray.front())
    markers.objects.push_back({kTrayId, false, {}, script.tray_size, Eigen::Vector3i(kTrayBgr[2], kTrayBgr[1], kTrayBgr[0])});

  return render_demonstration(o, out_dir, assets, script, bounds, camera, markers, script.truth(), t0);
}

CellSynthOutput write_synthetic_cell_demonstration(const CellSynthOptions& o, const std::string& out_dir) {
  const auto t0 = std::chrono::steady_clock::now();
  const SynthOptions& ro = o.render;
  if (ro.noise_sigma < 0 || ro.blur_px < 0) throw InputError("synth options", "noise/blur", "must be >= 0");
  if (ro.lighting < 0 || ro.lighting >= 1) throw InputError("synth options", "lighting", "must be in [0, 1)");
  if (!(ro.time_scale > 0.05 && ro.time_scale <= 4.0)) throw InputError("synth options", "time_scale", "must be in (0.05, 4]");
  const Cell cell = load_cell(o.cell);
  MeshCache cache;
  CellSceneOptions scene_options;
  scene_options.data_dir = ro.data_dir;
  scene_options.load_visual_meshes = true;
  scene_options.mesh_cache = &cache;
  const Scene scene = build_cell_scene(cell, scene_options);
  const SceneState start = cell_start_state(cell, scene);
  CellSynthOutput out;
  if (o.script.empty() && o.picks < 1) throw InputError("synth options", "picks", "must be >= 1");
  std::error_code ec;
  fs::create_directories(out_dir, ec);
  if (!fs::is_directory(out_dir)) throw InputError(out_dir, "", "cannot create the output folder");
  const Assets assets = scene_assets(scene);
  std::vector<Eigen::AlignedBox3d> bounds;
  for (const auto& p : assets.parts) bounds.push_back(p.bounds().cast<double>());
  MarkerIds ids;
  std::vector<MarkedObject> marked = cell_part_markers(cell, object_ids(scene), bounds, &ids);
  std::vector<std::vector<ObjectMarker>> part_markers;
  for (const auto& o : marked) part_markers.push_back(o.markers);
  PickTiming timing;
  auto scaled = [&](int frames) { return std::max(4, static_cast<int>(std::lround(frames * ro.time_scale))); };
  timing.lead_in = scaled(timing.lead_in);
  timing.carry = scaled(timing.carry);
  timing.between = scaled(timing.between);

  // Random picks whose part would rest where no camera view shows one of its markers (inside a
  // shelf behind its side board) are drawn again: a monocular demonstration cannot show them.
  // The redraws follow from the seed, so a seed still gives one video.
  constexpr int kDraws = 10;
  std::vector<ScriptedPick> picks;
  Demonstration truth;
  DemoScript script;
  Camera camera;
  for (int draw = 0; draw < (o.script.empty() ? kDraws : 1); ++draw) {
    if (!o.script.empty()) {
      picks = load_pick_script(o.script, scene);
    } else {
      const RandomPickReport r = random_picks(scene, start, o.picks, ro.seed + static_cast<std::uint64_t>(draw) * 1000003);
      picks = r.picks;
      out.failure = r.failure;
    }
    if (picks.empty()) throw InputError(o.cell, "parts", "no pick to demonstrate: " + out.failure);
    truth = demonstration_from_picks(scene, start, picks, scene.name, timing);
    // Two seconds after the last release, as a recording that stops once the demonstrator is
    // done: the hand pulls away (26 frames) and the parts are seen at rest.
    script = make_demo_script(truth, start.objects, bounds, scaled(60));
    CameraPlacementReport seen;
    camera = place_camera(script, assets.obstacles, part_markers, {}, &seen);
    out.redraws = draw;
    if (seen.blind_rests == 0) break;
  }
  out.picks = static_cast<int>(picks.size());
  if (!ro.part_markers)
    for (auto& m : marked) m.markers.clear();
  add_hand(script, camera.world_T_camera->translation());
  if (ro.board) {
    // The board's ids must not be read as a part's when both use the same dictionary.
    const MarkerBoard board = extrinsics_board(cell.marker_dictionary == kDictionary ? ids.take(6) : 90);
    // On a top with a free spot the camera sees; else on a top where the hand and the carried
    // parts pass later (extract reads the board from the first frames that show it: the first
    // second is kept clear, and where parts rest); else the same with the camera drawn back to
    // see the largest top whole, as a person sets up a camera over the table; else on a free
    // floor tile near the camera (tiles under furniture are left out: the obstacle test does not
    // see into a box), where it is seen small and the camera's pose comes out worse.
    const auto& tops = assets.board_tops;
    auto on_a_top = [&](const DemoScript& s, const Camera& cam) -> std::optional<MarkerBoard> {
      DemoScript first_second = s;
      first_second.hand.resize(std::min(first_second.hand.size(), static_cast<size_t>(std::lround(s.fps))));
      for (const auto& c : s.carries)  // where the parts rest, not where they pass later
        for (int f = c.grasp + 1; f < c.release; ++f) first_second.poses[f][c.object] = s.poses[c.grasp][c.object];
      for (const DemoScript* variant : {&s, static_cast<const DemoScript*>(&first_second)})
        for (const auto& [top, size] : tops)
          if (auto b = place_board(*variant, top, size, cam, assets.obstacles, board)) return b;
      return std::nullopt;
    };
    camera.board = on_a_top(script, camera);
    if (!camera.board && !tops.empty()) {
      CameraPlacementOptions wider;
      const auto& [top, size] = tops.front();
      for (int c = 0; c < 4; ++c)
        wider.also_in_view.push_back(top * Eigen::Vector3d((c & 1 ? 0.5 : -0.5) * size.x(), (c & 2 ? 0.5 : -0.5) * size.y(), 0.0));
      Camera back = place_camera(script, assets.obstacles, part_markers, wider);
      DemoScript with_hand = script;
      add_hand(with_hand, back.world_T_camera->translation());
      if (auto b = on_a_top(with_hand, back)) {
        camera = back;
        camera.board = b;
        script = std::move(with_hand);
      }
    }
    std::vector<std::pair<double, Pose>> tiles;
    const double tile = 0.5;
    const Eigen::Vector3d eye = camera.world_T_camera->translation();
    for (int i = -6; i <= 6; ++i)
      for (int j = -6; j <= 6; ++j) {
        const Eigen::Vector2d c(eye.x() + i * tile, eye.y() + j * tile);
        const Eigen::AlignedBox2d t(c - Eigen::Vector2d::Constant(tile / 2), c + Eigen::Vector2d::Constant(tile / 2));
        bool free = true;
        for (const auto& b : assets.obstacles)
          free = free && !(b.min().z() < 0.05 && t.intersects(Eigen::AlignedBox2d(b.min().head<2>(), b.max().head<2>())));
        Pose floor = Pose::Identity();
        floor.translation() << c.x(), c.y(), 0.0;
        if (free) tiles.push_back({(c - eye.head<2>()).norm(), floor});
      }
    std::sort(tiles.begin(), tiles.end(), [](auto& a, auto& b) { return a.first < b.first; });
    for (const auto& t : tiles)
      if (!camera.board) camera.board = place_board(script, t.second, Eigen::Vector2d(tile, tile), camera, assets.obstacles, board);
    DemoScript parts_only = script;  // last: wherever the parts leave room, the hand's coming in hides it
    parts_only.hand.clear();
    for (const auto& [top, size] : tops)
      if (!camera.board) camera.board = place_board(parts_only, top, size, camera, assets.obstacles, board);
  }

  MarkerScene markers;
  markers.task = scene.name;
  markers.cell = fs::relative(fs::absolute(o.cell), fs::absolute(out_dir)).string();
  markers.robot = scene.robot.name;
  markers.camera = "camera.json";
  markers.dictionary = cell.marker_dictionary;
  markers.objects = marked;
  static_cast<SynthOutput&>(out) = render_demonstration(ro, out_dir, assets, script, bounds, camera, markers, truth, t0);
  if (out.cancelled) return out;

  // The intrinsics calibration video, rendered with the same intrinsics.
  BoardVideoOptions bo;
  bo.camera = camera;
  bo.camera.world_T_camera.reset();
  bo.camera.board.reset();
  bo.views = o.calibration_views;
  bo.seed = ro.seed;
  bo.noise_sigma = ro.noise_sigma;
  bo.fourcc = ro.fourcc;
  bo.cancel = ro.cancel;
  const BoardVideoOutput b = write_board_video(bo, out_dir);
  out.cancelled = b.cancelled;
  out.calibration_video = b.video;
  out.board = b.board;
  out.camera_truth = b.camera_truth;
  out.render_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return out;
}

MarkerScene cell_marker_scene(const std::string& cell_file, const std::string& data_dir) {
  const Cell cell = load_cell(cell_file);
  CellSceneOptions scene_options;
  scene_options.data_dir = data_dir;
  scene_options.load_visual_meshes = true;
  const Scene scene = build_cell_scene(cell, scene_options);
  std::vector<Eigen::AlignedBox3d> bounds;
  for (const auto& p : scene_assets(scene).parts) bounds.push_back(p.bounds().cast<double>());
  MarkerScene markers;
  markers.task = scene.name;
  markers.robot = scene.robot.name;
  markers.dictionary = cell.marker_dictionary;
  markers.objects = cell_part_markers(cell, object_ids(scene), bounds);
  return markers;
}

}  // namespace demoplan::perception
