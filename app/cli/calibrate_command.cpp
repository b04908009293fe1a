// demoplan-cli calibrate: a camera's intrinsics from a video or a folder of images of a ChArUco
// board (issue 15); writes a demoplan-camera file.
#include <iomanip>
#include <iostream>
#include <memory>

#include <nlohmann/json.hpp>

#include "app/cli/command.h"
#include "app/cli/video_commands.h"
#include "perception/camera/charuco_calibration.h"

namespace demoplan::cli {

namespace {

struct CalibrateCliOptions {
  std::string source, board, out;
  perception::CharucoCalibrationOptions calibration;
  bool json = false;
};

int run_calibrate(CalibrateCliOptions o) {
  const perception::CharucoBoard board = perception::load_charuco_board(o.board);
  int shown = 0;  // progress on stderr in tenths, not a line per view
  o.calibration.progress = [&](int done, int total) {
    if (done * 10 >= (shown + 1) * total || done == total) {
      shown = done * 10 / total;
      std::cerr << "  views looked at " << done << "/" << total << "\n";
    }
  };
  const perception::CharucoCalibration r = perception::calibrate_charuco(o.source, board, o.calibration);
  perception::save_camera(o.out, r.camera);
  const perception::Camera& c = r.camera;
  std::cerr << std::fixed << std::setprecision(3) << "calibrated " << o.source << " (" << r.frames << " frames, "
            << r.views.size() << " looked at): RMS " << r.rms_px << " px over " << r.views_used << " views, "
            << r.views_rejected << " rejected\n"
            << "  fx " << c.fx << "  fy " << c.fy << "  cx " << c.cx << "  cy " << c.cy << "  ("
            << c.image_size.width << "x" << c.image_size.height << ")\n  distortion";
  for (double d : c.distortion) std::cerr << " " << d;
  std::cerr << "\n";
  for (const auto& v : r.views) {
    std::cerr << "  " << (v.image.empty() ? "frame " + std::to_string(v.frame) : v.image) << "  " << v.corners
              << " corners  ";
    if (v.used) std::cerr << "error " << v.error_px << " px\n";
    else std::cerr << "rejected: " << v.rejected << "\n";
  }
  std::cerr << "  wrote " << o.out << " in " << std::setprecision(1) << r.seconds << " s\n" << std::defaultfloat;
  if (o.json) {
    nlohmann::json views = nlohmann::json::array();
    for (const auto& v : r.views) {
      nlohmann::json j{{"frame", v.frame}, {"corners", v.corners}, {"used", v.used}, {"sharpness", v.sharpness}};
      if (!v.image.empty()) j["image"] = v.image;
      if (v.used) j["error_px"] = v.error_px;
      else j["rejected"] = v.rejected;
      views.push_back(j);
    }
    std::cout << nlohmann::json{{"source", o.source},
                                {"camera", o.out},
                                {"rms_px", r.rms_px},
                                {"views_used", r.views_used},
                                {"views_rejected", r.views_rejected},
                                {"frames", r.frames},
                                {"fx", c.fx},
                                {"fy", c.fy},
                                {"cx", c.cx},
                                {"cy", c.cy},
                                {"image_size", {c.image_size.width, c.image_size.height}},
                                {"distortion", c.distortion},
                                {"per_view", views},
                                {"time_s", r.seconds}}
                     .dump()
              << std::endl;
  }
  return kOk;
}

}  // namespace

Command register_calibrate_command(CLI::App& app) {
  auto o = std::make_shared<CalibrateCliOptions>();
  CLI::App* sub = add_video_subcommand(app, "calibrate");
  sub->add_option("source", o->source, "video (mp4, avi, mkv) or folder of images")->required();
  sub->add_option("--board", o->board, "the board (demoplan-charuco-board JSON, as `board` writes it)")->required();
  sub->add_option("--out", o->out, "camera file to write (demoplan-camera JSON)")->required();
  sub->add_option("--max-views", o->calibration.max_views, "frames looked at, spread evenly over the video")
      ->check(CLI::Range(3, 1000))->capture_default_str();
  sub->add_option("--min-corners", o->calibration.min_corners, "chessboard corners a view needs")
      ->check(CLI::Range(4, 10000))->capture_default_str();
  sub->add_flag("--json", o->json, "print one JSON object on stdout");
  return {sub, [o] { return run_calibrate(*o); }};
}

}  // namespace demoplan::cli
