#include "core/project/project.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include "core/error.h"
#include "core/io/stored_path.h"

namespace demoplan {

namespace fs = std::filesystem;

namespace {

Json result_to_json(const ResultSummary& r, const std::string& file) {
  return Json{{"path", to_stored(r.path, file)},
              {"solved", r.solved},
              {"valid", r.valid},
              {"message", r.message},
              {"validated_against", r.validated_against},
              {"planning_time_s", r.planning_time_s},
              {"iterations", r.iterations},
              {"trees", r.trees},
              {"nodes", r.nodes},
              {"length_robot_rad", r.length_robot_rad},
              {"length_object_m", r.length_object_m},
              {"length_object_rad", r.length_object_rad},
              {"grasps", r.grasps},
              {"gripper_closes", r.gripper_closes},
              {"shortened", r.shortened},
              {"demonstration_digest", r.demonstration_digest}};
}

ResultSummary result_from_json(const JsonField& j, const std::string& file) {
  ResultSummary r;
  r.path = from_stored(j["path"].string(), file);
  r.solved = j["solved"].boolean();
  r.valid = j["valid"].boolean();
  r.message = j["message"].string();
  r.validated_against = j.has("validated_against") ? j["validated_against"].string() : "";
  r.planning_time_s = j["planning_time_s"].number();
  // Counts stored as JSON numbers: converted only within range (a double beyond the range of
  // long or size_t makes the conversion undefined behaviour).
  const double iterations = j["iterations"].number();
  if (std::abs(iterations) > 1e15) j["iterations"].fail("is out of range");
  r.iterations = static_cast<long>(iterations);
  r.trees = j["trees"].integer();
  const double nodes = j["nodes"].number();
  if (nodes < 0) j["nodes"].fail("must be >= 0");
  if (nodes > 1e15) j["nodes"].fail("is out of range");
  r.nodes = static_cast<size_t>(nodes);
  r.length_robot_rad = j["length_robot_rad"].number();
  r.length_object_m = j["length_object_m"].number();
  r.length_object_rad = j["length_object_rad"].number();
  r.grasps = j["grasps"].integer();
  // Projects saved before the gripper closes were recorded: the benchmark's count stands in.
  r.gripper_closes = j.has("gripper_closes") ? j["gripper_closes"].integer() : r.grasps;
  r.shortened = j.has("shortened") && j["shortened"].boolean();
  r.demonstration_digest = j.has("demonstration_digest") ? j["demonstration_digest"].string() : "";
  return r;
}

}  // namespace

ResultSummary summarize(const PlanReport& report, const std::string& validated_against) {
  ResultSummary s;
  const PlanResult& p = report.plan;
  s.solved = p.solved;
  s.planning_time_s = p.planning_time_s;
  s.iterations = p.iterations;
  s.trees = p.trees;
  s.nodes = p.nodes;
  if (!p.solved) {
    s.message = p.message;
    return s;
  }
  const ValidationReport& v = report.validation;
  s.valid = v.valid;
  s.message = v.message;
  s.validated_against = validated_against;
  s.length_robot_rad = v.length.robot;
  s.length_object_m = v.length.object_translation;
  s.length_object_rad = v.length.object_rotation;
  s.grasps = v.grasps;
  s.gripper_closes = v.gripper_closes;
  s.shortened = report.shortened;
  return s;
}

std::string SceneReference::describe() const {
  if (is_cell()) return fs::path(cell).filename().string();
  if (base) {
    char where[96];
    std::snprintf(where, sizeof where, " at x %.3f, y %.3f, yaw %.0f deg", base->x, base->y, base->yaw * 180 / M_PI);
    return task + ", " + robot + where;
  }
  return task + ", " + robot + " pose " + std::to_string(pose);
}

Json project_to_json(const Project& p, const std::string& file) {
  Json scene = p.scene.is_cell() ? Json{{"cell", to_stored(p.scene.cell, file)}}
                                 : Json{{"task", p.scene.task}, {"robot", p.scene.robot}, {"pose", p.scene.pose}};
  if (!p.scene.data_dir.empty()) scene["data_dir"] = to_stored(p.scene.data_dir, file);
  if (p.scene.base && !p.scene.is_cell())
    scene["base"] = {{"x", p.scene.base->x}, {"y", p.scene.base->y}, {"z", p.scene.base->z}, {"yaw", p.scene.base->yaw}};
  Json j{{"format", kProjectFormat},
         {"version", kProjectVersion},
         {"units", "metres, radians, seconds; paths relative to this file"},
         {"scene", scene},
         {"video", to_stored(p.video, file)},
         {"camera", to_stored(p.camera, file)},
         {"markers", to_stored(p.markers, file)},
         {"demonstration", demonstration_to_json(p.demonstration)},
         {"planner", planner_settings_to_json(p.planner)},
         {"result", p.result ? result_to_json(*p.result, file) : Json(nullptr)},
         {"view", {{"frame", p.frame}}}};
  if (!p.tracker_corrections.empty()) {
    Json corrections = Json::array();
    for (const auto& c : p.tracker_corrections)
      corrections.push_back({{"id", c.id}, {"frame", c.frame}, {"world_T_object", pose_matrix_json(c.world_T_object)}});
    j["tracker_corrections"] = corrections;
  }
  return j;
}

Project project_from_json(const Json& json, const std::string& file) {
  const JsonField root(json, file);
  check_format(root, kProjectFormat, kProjectVersion, "project");
  Project p;
  const JsonField scene = root["scene"];
  if (scene.has("cell")) {
    p.scene.cell = from_stored(scene["cell"].string(), file);
    if (p.scene.cell.empty()) scene["cell"].fail("must name a cell file");
  } else {
    p.scene.task = scene["task"].string();
    p.scene.robot = scene["robot"].string();
    p.scene.pose = scene["pose"].integer();
    if (p.scene.pose < 0) scene["pose"].fail("must be >= 0");
    if (scene.has("base")) {
      const JsonField b = scene["base"];
      p.scene.base = BasePose{b["x"].number(), b["y"].number(), b["z"].number(), b["yaw"].number()};
    }
  }
  if (scene.has("data_dir")) p.scene.data_dir = from_stored(scene["data_dir"].string(), file);
  p.video = root.has("video") ? from_stored(root["video"].string(), file) : "";
  p.camera = root.has("camera") ? from_stored(root["camera"].string(), file) : "";
  p.markers = root.has("markers") ? from_stored(root["markers"].string(), file) : "";
  const JsonField demo = root["demonstration"];
  if (!demo.value().is_object()) demo.fail("must be a demoplan-demonstration object");
  p.demonstration = demonstration_from_json(demo.value(), file + ": demonstration");
  if (root.has("planner")) p.planner = planner_settings_from_json(root["planner"]);
  if (root.has("result") && !root["result"].is_null()) p.result = result_from_json(root["result"], file);
  if (root.has("tracker_corrections")) {
    const auto& ids = p.demonstration.object_ids;
    p.tracker_corrections = read_part_corrections(
        root["tracker_corrections"], 0,
        [&](const std::string& id) { return std::find(ids.begin(), ids.end(), id) != ids.end(); },
        "is not in the demonstration", [](const JsonField& f) { return f.pose(); });
  }
  if (root.has("view") && root["view"].has("frame")) p.frame = std::max(0, root["view"]["frame"].integer());
  return p;
}

void save_project(const std::string& file, const Project& project) {
  write_json_file_atomic(file, project_to_json(project, file), 1);
}

Project load_project(const std::string& file) {
  std::error_code ec;
  if (!fs::exists(file, ec)) throw InputError(file, "", "no such file");
  if (fs::is_directory(file, ec)) throw InputError(file, "", "is a folder, not a project file");
  return project_from_json(read_json_file(file), file);
}

std::string demonstration_digest(const Demonstration& demo) {
  const std::string text = demonstration_to_json(demo).dump();
  std::uint64_t h = 1469598103934665603ull;
  for (unsigned char c : text) {
    h ^= c;
    h *= 1099511628211ull;
  }
  char buf[17];
  std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(h));
  return buf;
}

}  // namespace demoplan
