// demoplan-cli synth: render a synthetic demonstration video of a benchmark task with its
// camera, marker scene and ground truth.
#include <iostream>
#include <memory>

#include <nlohmann/json.hpp>

#include "app/cli/command.h"
#include "app/cli/video_commands.h"
#include "perception/synthetic/synthetic_video.h"

namespace demoplan::cli {

namespace {

struct SynthCliOptions {
  perception::SynthOptions synth;
  std::string cell, script;  // a cell's demonstration in place of a benchmark task's
  int picks = 3;
  int calibration_views = 30;
  std::string out;
  bool no_board = false;
  bool no_markers = false;
  bool json = false;
};

int run_cell_synth(const SynthCliOptions& o) {
  perception::CellSynthOptions c;
  c.render = o.synth;
  c.cell = o.cell;
  c.picks = o.picks;
  c.script = o.script;
  c.calibration_views = o.calibration_views;
  const perception::CellSynthOutput r = perception::write_synthetic_cell_demonstration(c, o.out);
  std::cerr << "synthetic demonstration of cell " << o.cell << " (" << r.picks << " picks)\n"
            << "  frames       " << r.frames << " at " << r.fps << " fps\n"
            << "  events       " << r.events << "\n"
            << "  video        " << r.video << "\n"
            << "  camera       " << r.camera << "\n"
            << "  scene        " << r.scene << "\n"
            << "  truth        " << r.truth << ", " << r.truth_tracks << "\n"
            << "  init         " << r.init << "\n"
            << "  calibration  " << r.calibration_video << ", " << r.board << ", " << r.camera_truth << "\n";
  if (!r.failure.empty()) std::cerr << "  fewer picks than asked: " << r.failure << "\n";
  if (r.redraws > 0)
    std::cerr << "  picks drawn " << r.redraws + 1 << " times: a part would have rested where no camera view shows it\n";
  std::cerr << "  time         " << r.render_seconds << " s\n";
  if (o.json)
    std::cout << nlohmann::json{{"cell", o.cell},          {"picks", r.picks},        {"failure", r.failure}, {"redraws", r.redraws},
                                {"frames", r.frames},      {"fps", r.fps},            {"events", r.events},
                                {"video", r.video},        {"camera", r.camera},      {"scene", r.scene},
                                {"truth", r.truth},        {"truth_tracks", r.truth_tracks}, {"init", r.init},
                                {"calibration_video", r.calibration_video},
                                {"board", r.board},        {"camera_truth", r.camera_truth},
                                {"render_time_s", r.render_seconds}}
                     .dump()
              << std::endl;
  return r.failure.empty() ? kOk : kFailed;
}

int run_synth(SynthCliOptions o) {
  o.synth.board = !o.no_board;
  o.synth.part_markers = !o.no_markers;
  if (!o.cell.empty()) return run_cell_synth(o);
  const perception::SynthOutput r = perception::write_synthetic_demonstration(o.synth, o.out);
  std::cerr << "synthetic demonstration of " << o.synth.task << " (" << o.synth.robot << " pose " << o.synth.robot_pose
            << ")\n"
            << "  frames      " << r.frames << " at " << r.fps << " fps\n"
            << "  events      " << r.events << "\n"
            << "  video       " << r.video << "\n"
            << "  camera      " << r.camera << "\n"
            << "  scene       " << r.scene << "\n"
            << "  truth       " << r.truth << ", " << r.truth_tracks << "\n"
            << "  init        " << r.init << "\n";
  if (!r.bop_csv.empty()) std::cerr << "  detections  " << r.bop_csv << ", " << r.hands << "\n";
  std::cerr << "  time        " << r.render_seconds << " s\n";
  if (o.json) {
    nlohmann::json j{{"task", o.synth.task}, {"frames", r.frames}, {"fps", r.fps},     {"events", r.events},
                     {"video", r.video},     {"camera", r.camera}, {"scene", r.scene}, {"truth", r.truth},
                     {"truth_tracks", r.truth_tracks}, {"init", r.init}, {"render_time_s", r.render_seconds}};
    if (!r.bop_csv.empty()) j["bop_csv"] = r.bop_csv, j["hands"] = r.hands;
    std::cout << j.dump() << std::endl;
  }
  return kOk;
}

}  // namespace

Command register_synth_command(CLI::App& app) {
  auto o = std::make_shared<SynthCliOptions>();
  CLI::App* sub = add_video_subcommand(app, "synth");
  auto* task = sub->add_option("--task", o->synth.task, "task as <task>_<demo>, e.g. shelf_1")->capture_default_str();
  auto* cell = sub->add_option("--cell", o->cell, "a cell file (docs/cell.md) in place of a benchmark task")->excludes(task);
  sub->add_option("--picks", o->picks, "with --cell: random doable picks to demonstrate")
      ->check(CLI::Range(1, 50))->capture_default_str()->needs(cell);
  sub->add_option("--script", o->script, "with --cell: a demoplan-pick-script file in place of random picks")
      ->needs(cell);
  sub->add_option("--calibration-views", o->calibration_views, "with --cell: frames of calibration.mp4")
      ->check(CLI::Range(6, 200))->capture_default_str()->needs(cell);
  sub->add_option("--robot", o->synth.robot, "robot the scene is for: panda, ur5, kmr_iiwa")->capture_default_str();
  sub->add_option("--pose", o->synth.robot_pose, "robot base pose id of the task")->capture_default_str();
  sub->add_option("--out", o->out, "output folder (video.mp4, camera.json, scene.json, truth.json, init.json)")->required();
  sub->add_option("--noise", o->synth.noise_sigma, "Gaussian image noise, grey levels")
      ->check(CLI::NonNegativeNumber)->capture_default_str();
  sub->add_option("--blur", o->synth.blur_px, "linear motion blur length, pixels")
      ->check(CLI::NonNegativeNumber)->capture_default_str();
  sub->add_option("--lighting", o->synth.lighting,
                  "the light's brightness varies by this fraction over the video (0.3: 70-130 %), its colour by half as much")
      ->check(CLI::Range(0.0, 0.95))->capture_default_str();
  sub->add_flag("--occlusion", o->synth.occlusion, "a pole passes in front of every carried part");
  sub->add_option("--seed", o->synth.seed, "random seed (noise, blur direction, simulated detections, a cell's picks)")->capture_default_str();
  sub->add_option("--time-scale", o->synth.time_scale, "scale of every frame index (< 1: shorter video)")
      ->check(CLI::Range(0.1, 4.0))->capture_default_str();
  sub->add_option("--fourcc", o->synth.fourcc, "video codec: mp4v, avc1, MJPG, FFV1")->capture_default_str();
  sub->add_flag("--detections", o->synth.detections, "also write simulated bop.csv and hands.json");
  sub->add_flag("--no-board", o->no_board, "no ArUco board on the table");
  sub->add_flag("--no-markers", o->no_markers,
                "no markers on the parts (for the model-based tracker; init.json gives the parts' poses in frame 0)");
  sub->add_flag("--json", o->json, "print one JSON object on stdout");
  add_data_dir_option(*sub, o->synth.data_dir);
  return {sub, [o] { return run_synth(*o); }};
}

}  // namespace demoplan::cli
