// demoplan-cli new: a project file from a benchmark task, with its video, camera and marker
// scene checked and stored, ready to open in the desktop application.
#include <filesystem>
#include <iostream>
#include <memory>

#include <nlohmann/json.hpp>

#include "app/cli/command.h"
#include "core/error.h"
#include "core/project/new_project.h"
#include "perception/camera/camera_model.h"
#include "perception/markers/marker_scene.h"
#include "perception/video/video_reader.h"

namespace demoplan::cli {

namespace {

struct NewOptions {
  std::string spec, out, video, camera, markers, data_dir;
  bool json = false;
};

SceneReference parse_spec(const std::string& spec) {
  SceneReference ref;
  const auto a = spec.find(':'), b = spec.find(':', a == std::string::npos ? a : a + 1);
  bool ok = a != std::string::npos && b != std::string::npos && a > 0 && b > a + 1 && b + 1 < spec.size();
  if (ok) {
    ref.task = spec.substr(0, a);
    ref.robot = spec.substr(a + 1, b - a - 1);
    try {
      size_t used = 0;
      ref.pose = std::stoi(spec.substr(b + 1), &used);
      ok = used == spec.size() - b - 1;
    } catch (const std::exception&) {
      ok = false;
    }
  }
  if (!ok) throw InputError("command line", "TASK:ROBOT:POSE", "'" + spec + "' is not like shelf_1:panda:1");
  return ref;
}

std::string absolute(const std::string& file) {
  return file.empty() ? file : std::filesystem::absolute(file).lexically_normal().string();
}

int run_new(const NewOptions& o) {
  const SceneReference ref = parse_spec(o.spec);
  NewProject made = new_benchmark_project(o.data_dir, ref);
  Project& p = made.project;
  // Checked here as the desktop application would check them, so the project opens cleanly.
  if (!o.video.empty()) perception::VideoReader check(o.video);
  if (!o.camera.empty()) perception::load_camera(o.camera);
  if (!o.markers.empty()) perception::load_marker_scene(o.markers);
  if (o.data_dir != default_data_dir()) p.scene.data_dir = absolute(o.data_dir);
  p.video = absolute(o.video);
  p.camera = absolute(o.camera);
  p.markers = absolute(o.markers);
  save_project(o.out, p);
  for (const auto& note : made.deck.notes()) std::cerr << "on the robot's deck: " << note << "\n";
  std::cerr << "wrote " << o.out << " (" << ref.task << ", " << ref.robot << " pose " << ref.pose << ", "
            << p.demonstration.events.size() << " events)\n";
  if (o.json)
    std::cout << nlohmann::json{{"project", o.out},
                                {"task", ref.task},
                                {"robot", ref.robot},
                                {"pose", ref.pose},
                                {"events", p.demonstration.events.size()},
                                {"deck_notes", made.deck.notes()}}
                     .dump()
              << std::endl;
  return kOk;
}

}  // namespace

Command register_new_command(CLI::App& app) {
  auto o = std::make_shared<NewOptions>();
  CLI::App* sub = app.add_subcommand("new", "create a project file from a benchmark task");
  sub->add_option("scene", o->spec, "TASK:ROBOT:POSE, e.g. shelf_1:panda:1")->required();
  sub->add_option("--out", o->out, "project file to write (.demoplan)")->required();
  sub->add_option("--video", o->video, "video of the demonstration")->check(CLI::ExistingFile);
  sub->add_option("--camera", o->camera, "camera calibration (demoplan-camera or OpenCV)")->check(CLI::ExistingFile);
  sub->add_option("--markers", o->markers, "marker scene: which markers are on which part")->check(CLI::ExistingFile);
  sub->add_flag("--json", o->json, "print one JSON object on stdout");
  add_data_dir_option(*sub, o->data_dir);
  return {sub, [o] { return run_new(*o); }};
}

}  // namespace demoplan::cli
