#pragma once
// Synthetic demonstration videos of benchmark tasks, for tests, benchmarks and the bundled
// sample: the task's furniture and textured YCB-V parts with ArUco markers on their faces, a
// hand carrying each part from its grasp to its release, seen by a calibrated camera, with the
// ground truth beside the video. Headless and deterministic for a given seed.
//
// Writes into the output folder: video.mp4 (video.mkv for FFV1, video.avi for MJPG), camera.json (demoplan-camera), scene.json
// (demoplan-marker-scene), truth.json (demoplan-demonstration), truth.tracks.json (every part's
// true pose in every frame, in the tracks file of an extraction: tracks_file.h), init.json
// (demoplan-tracker-init: every part's pose in frame 0, where a model-based tracker starts) and,
// on request, bop.csv and hands.json (simulated outputs of a 6D pose estimator and of a
// hand-contact detector).
#include <atomic>
#include <functional>
#include <string>

#include "perception/markers/marker_scene.h"

namespace demoplan::perception {

struct SynthOptions {
  std::string data_dir;  // benchmark data folder (gtamp)
  std::string task = "shelf_1";
  std::string robot = "panda";  // the robot scene the demonstration is for (recorded in scene.json)
  int robot_pose = 0;
  double noise_sigma = 0.0;  // grey levels
  double blur_px = 0.0;      // motion blur length, pixels
  double lighting = 0.0;     // the light's brightness varies by this fraction over the video (image_degradation.h)
  bool occlusion = false;    // a pole passes in front of every carried part
  unsigned seed = 1;
  double time_scale = 1.0;   // < 1: a shorter video
  std::string fourcc = "mp4v";
  bool board = true;         // an ArUco board on the table for the camera extrinsics
  bool part_markers = true;  // false: parts without markers (the camera is placed as with them)
  bool detections = false;   // also write bop.csv and hands.json
  std::function<void(int done, int total)> progress;
  const std::atomic<bool>* cancel = nullptr;
};

struct SynthOutput {
  std::string video, camera, scene, truth, truth_tracks, init, bop_csv, hands;
  int frames = 0;
  int events = 0;
  double fps = 30.0;
  double render_seconds = 0.0;
  bool cancelled = false;  // then no file was written
};

// Throws InputError for an unknown task, robot or pose, or a task without subgoals.
SynthOutput write_synthetic_demonstration(const SynthOptions& options, const std::string& out_dir);

// A synthetic demonstration of a robot cell (core/cell): its furniture and parts (with the
// cell's own markers where a part has them, else one on each face of its box), picks drawn at
// random among the doable ones (cell_picks.h) or read from a pick script, and the hand carrying
// each part. Besides the files above (scene.json names the cell), writes the calibration video
// of the same camera: calibration.mp4, board.json, camera_truth.json (board_video.h).
struct CellSynthOptions {
  SynthOptions render;       // noise, blur, seed (also of the picks), time_scale, fourcc, board, progress
  std::string cell;          // cell file
  int picks = 3;             // random picks, when no script
  std::string script;        // demoplan-pick-script file
  int calibration_views = 30;
};

struct CellSynthOutput : SynthOutput {
  std::string calibration_video, board, camera_truth;
  int picks = 0;
  std::string failure;  // fewer random picks than asked: why (the video shows those found)
  int redraws = 0;      // random picks drawn again because a part would rest where no view shows it
};

// Throws InputError for a bad cell or pick script.
CellSynthOutput write_synthetic_cell_demonstration(const CellSynthOptions& options, const std::string& out_dir);

// The markers on a cell's parts, as the synthetic video shows them and `extract` reads them (for
// a printed sheet that matches the video): cell_part_markers over the parts' drawn meshes.
MarkerScene cell_marker_scene(const std::string& cell_file, const std::string& data_dir);

}  // namespace demoplan::perception
