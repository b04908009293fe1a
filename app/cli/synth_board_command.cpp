// demoplan-cli synth-board: a synthetic calibration video of a ChArUco board seen by a camera of
// known intrinsics, with the board file and the true camera (issue 15).
#include <iostream>
#include <memory>

#include <nlohmann/json.hpp>

#include "app/cli/command.h"
#include "app/cli/video_commands.h"
#include "perception/synthetic/board_video.h"

namespace demoplan::cli {

namespace {

struct SynthBoardCliOptions {
  perception::BoardVideoOptions video;
  std::string out;
  bool json = false;
};

int run_synth_board(const SynthBoardCliOptions& o) {
  const perception::BoardVideoOutput r = perception::write_board_video(o.video, o.out);
  const perception::Camera& c = o.video.camera;
  std::cerr << "synthetic calibration video: " << r.frames << " views of a " << o.video.board.squares_x << " x "
            << o.video.board.squares_y << " ChArUco board, noise " << o.video.noise_sigma << ", blur "
            << o.video.blur_px << " px, seed " << o.video.seed << "\n"
            << "  truth       fx " << c.fx << "  fy " << c.fy << "  cx " << c.cx << "  cy " << c.cy << "\n"
            << "  video       " << r.video << "\n"
            << "  board       " << r.board << "\n"
            << "  camera      " << r.camera_truth << "\n"
            << "  time        " << r.seconds << " s\n";
  if (o.json)
    std::cout << nlohmann::json{{"video", r.video},         {"board", r.board}, {"camera_truth", r.camera_truth},
                                {"frames", r.frames},       {"fx", c.fx},       {"fy", c.fy},
                                {"cx", c.cx},               {"cy", c.cy},       {"render_time_s", r.seconds}}
                     .dump()
              << std::endl;
  return kOk;
}

}  // namespace

Command register_synth_board_command(CLI::App& app) {
  auto o = std::make_shared<SynthBoardCliOptions>();
  CLI::App* sub = add_video_subcommand(app, "synth-board");
  sub->add_option("--out", o->out, "output folder (calibration.mp4, board.json, camera_truth.json)")->required();
  sub->add_option("--views", o->video.views, "board poses, one frame each")->check(CLI::Range(1, 1000))->capture_default_str();
  sub->add_option("--noise", o->video.noise_sigma, "Gaussian image noise, grey levels")
      ->check(CLI::NonNegativeNumber)->capture_default_str();
  sub->add_option("--blur", o->video.blur_px, "linear motion blur length, pixels")
      ->check(CLI::NonNegativeNumber)->capture_default_str();
  sub->add_option("--seed", o->video.seed, "random seed (poses, noise, blur direction)")->capture_default_str();
  sub->add_flag("--json", o->json, "print one JSON object on stdout");
  return {sub, [o] { return run_synth_board(*o); }};
}

}  // namespace demoplan::cli
