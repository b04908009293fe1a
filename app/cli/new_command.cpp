// demoplan-cli new: a project file from a benchmark task or a cell, with its video, camera and marker
// scene checked and stored, ready to open in the desktop application.
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>

#include <nlohmann/json.hpp>

#include "app/cli/command.h"
#include "app/cli/video_commands.h"
#include "core/error.h"
#include "core/project/new_project.h"
#include "perception/camera/camera_model.h"
#include "perception/markers/marker_scene.h"
#include "perception/video/video_reader.h"

namespace demoplan::cli {

namespace {

struct NewOptions {
  std::string spec, cell, demo, out, video, camera, markers, data_dir;
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
  if (o.spec.empty() == o.cell.empty()) throw InputError("command line", "scene", "give TASK:ROBOT:POSE or --cell");
  std::optional<Demonstration> demo;
  if (!o.demo.empty()) demo = load_demonstration(o.demo);
  NewProject made = o.cell.empty() ? new_benchmark_project(o.data_dir, parse_spec(o.spec))
                                   : new_cell_project(o.data_dir, o.cell, demo ? &*demo : nullptr);
  const SceneReference& ref = made.project.scene;
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
  std::cerr << "wrote " << o.out << " (" << ref.describe() << ", " << p.demonstration.events.size() << " events)\n";
  if (o.json) {
    nlohmann::json j = ref.is_cell() ? nlohmann::json{{"cell", ref.cell}}
                                     : nlohmann::json{{"task", ref.task}, {"robot", ref.robot}, {"pose", ref.pose}};
    j.update(nlohmann::json{{"project", o.out}, {"events", p.demonstration.events.size()}, {"deck_notes", made.deck.notes()}});
    std::cout << j.dump() << std::endl;
  }
  return kOk;
}

}  // namespace

Command register_new_command(CLI::App& app) {
  auto o = std::make_shared<NewOptions>();
  CLI::App* sub = add_video_subcommand(app, "new");
  auto* spec = sub->add_option("scene", o->spec, "TASK:ROBOT:POSE, e.g. shelf_1:panda:1");
  sub->add_option("--cell", o->cell, "a cell file (docs/cell.md) in place of TASK:ROBOT:POSE")->excludes(spec);
  sub->add_option("--demo", o->demo, "with --cell: the demonstration to start from (default: none yet)")
      ->needs("--cell")->check(CLI::ExistingFile);
  sub->add_option("--out", o->out, "project file to write (.demoplan)")->required();
  sub->add_option("--video", o->video, "video of the demonstration")->check(CLI::ExistingFile);
  sub->add_option("--camera", o->camera, "camera calibration (demoplan-camera or OpenCV)")->check(CLI::ExistingFile);
  sub->add_option("--markers", o->markers, "marker scene: which markers are on which part")->check(CLI::ExistingFile);
  sub->add_flag("--json", o->json, "print one JSON object on stdout");
  add_data_dir_option(*sub, o->data_dir);
  return {sub, [o] { return run_new(*o); }};
}

}  // namespace demoplan::cli
