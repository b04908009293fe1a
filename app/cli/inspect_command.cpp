// demoplan-cli inspect: reads a project file and every file it names, as the desktop application
// opens it, and says what it holds; any bad input is one line naming the file and the field.
#include <iostream>
#include <memory>

#include <nlohmann/json.hpp>

#include "app/cli/command.h"
#include "app/cli/video_commands.h"
#include "core/error.h"
#include "core/project/project_scene.h"
#include "perception/camera/camera_model.h"
#include "perception/markers/marker_scene.h"
#include "perception/video/video_reader.h"

namespace demoplan::cli {

namespace {

struct InspectOptions {
  std::string project, data_dir;
  bool json = false;
};

int run_inspect(const InspectOptions& o) {
  const Project p = load_project(o.project);
  std::shared_ptr<const Scene> loaded;
  try {
    loaded = load_referenced_scene(p.scene, o.data_dir).scene;
  } catch (const InputError& e) {
    throw InputError(o.project, "scene", std::string("cannot load the scene it refers to: ") + e.what());
  }
  std::vector<std::string> ids;
  for (const auto& obj : loaded->objects) ids.push_back(obj.id);
  if (ids != p.demonstration.object_ids)
    throw InputError(o.project, "demonstration.objects", "do not match the objects of the scene " + p.scene.describe());
  int frames = 0;
  if (!p.video.empty()) frames = perception::VideoReader(p.video).frame_count();
  if (!p.camera.empty()) perception::load_camera(p.camera);
  if (!p.markers.empty()) perception::load_marker_scene(p.markers);
  std::cerr << o.project << ": " << p.scene.describe() << ", "
            << p.demonstration.events.size() << " events" << (p.video.empty() ? "" : ", video of ")
            << (p.video.empty() ? "" : std::to_string(frames) + " frames") << "\n";
  if (o.json) {
    nlohmann::json j = p.scene.is_cell()
                           ? nlohmann::json{{"cell", p.scene.cell}}
                           : nlohmann::json{{"task", p.scene.task}, {"robot", p.scene.robot}, {"pose", p.scene.pose}};
    j.update(nlohmann::json{{"project", o.project}, {"events", p.demonstration.events.size()}, {"video_frames", frames}});
    std::cout << j.dump() << std::endl;
  }
  return kOk;
}

}  // namespace

Command register_inspect_command(CLI::App& app) {
  auto o = std::make_shared<InspectOptions>();
  CLI::App* sub =
      add_video_subcommand(app, "inspect");
  sub->add_option("project", o->project, "project file (.demoplan)")->required();
  add_data_dir_option(*sub, o->data_dir);
  sub->add_flag("--json", o->json, "print one JSON object on stdout");
  return {sub, [o] { return run_inspect(*o); }};
}

}  // namespace demoplan::cli
