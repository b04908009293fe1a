#include "core/path/path.h"

#include "core/error.h"
#include "core/io/json_file.h"

namespace demoplan {

namespace {
constexpr const char* kFormat = "demoplan-path";
constexpr int kVersion = 1;

const char* action_name(GripperAction a) {
  switch (a) {
    case GripperAction::Grasp: return "grasp";
    case GripperAction::Release: return "release";
    default: return "none";
  }
}
}  // namespace

double Path::robot_length() const {
  double length = 0.0;
  for (size_t i = 1; i < waypoints.size(); ++i) length += (waypoints[i].q - waypoints[i - 1].q).norm();
  return length;
}

void save_path(const std::string& file, const Path& path) {
  Json waypoints = Json::array();
  for (const auto& w : path.waypoints) {
    Json objects = Json::array();
    for (const auto& T : w.objects) objects.push_back(pose_matrix_json(T));
    Json wp{{"q", std::vector<double>(w.q.data(), w.q.data() + w.q.size())},
            {"objects", objects},
            {"state", w.state},
            {"state_name", w.state_name},
            {"action", action_name(w.action)},
            {"approach", w.approach}};
    if (w.action != GripperAction::None) wp["object"] = w.object >= 0 ? path.object_ids.at(w.object) : "";
    waypoints.push_back(std::move(wp));
  }
  write_json_file_atomic(file, {{"format", kFormat},
                                {"version", kVersion},
                                {"units", "q in rad (revolute) and m (prismatic); objects as 4x4 row-major world poses in m"},
                                {"task", path.task},
                                {"robot", path.robot},
                                {"robot_pose", path.robot_pose},
                                {"joint_names", path.joint_names},
                                {"object_ids", path.object_ids},
                                {"waypoints", waypoints}});
}

Path load_path(const std::string& file) {
  const Json json = read_json_file(file);
  const JsonField root(json, file);
  check_format(root, kFormat, kVersion);
  Path p;
  p.task = root["task"].string();
  p.robot = root["robot"].string();
  p.robot_pose = root["robot_pose"].integer();
  for (size_t i = 0; i < root["joint_names"].size(); ++i) p.joint_names.push_back(root["joint_names"][i].string());
  for (size_t i = 0; i < root["object_ids"].size(); ++i) p.object_ids.push_back(root["object_ids"][i].string());
  const JsonField waypoints = root["waypoints"];
  for (size_t i = 0; i < waypoints.size(); ++i) {
    const JsonField w = waypoints[i];
    Waypoint wp;
    wp.q = w["q"].vector();
    if (wp.q.size() != static_cast<long>(p.joint_names.size()))
      w["q"].fail("has " + std::to_string(wp.q.size()) + " entries for " + std::to_string(p.joint_names.size()) + " joints");
    const JsonField objects = w["objects"];
    if (objects.size() != p.object_ids.size()) objects.fail("must have one pose per object");
    for (size_t o = 0; o < objects.size(); ++o) wp.objects.push_back(objects[o].pose());
    wp.state = w["state"].integer();
    wp.state_name = w["state_name"].string();
    wp.approach = w.has("approach") && w["approach"].boolean();
    const std::string action = w["action"].string();
    if (action == "grasp") wp.action = GripperAction::Grasp;
    else if (action == "release") wp.action = GripperAction::Release;
    else if (action != "none") w["action"].fail("must be 'none', 'grasp' or 'release'");
    if (wp.action != GripperAction::None) {
      const std::string id = w["object"].string();
      auto it = std::find(p.object_ids.begin(), p.object_ids.end(), id);
      if (it == p.object_ids.end()) w["object"].fail("'" + id + "' is not in object_ids");
      wp.object = static_cast<int>(it - p.object_ids.begin());
    }
    p.waypoints.push_back(std::move(wp));
  }
  if (p.waypoints.empty()) waypoints.fail("a path needs at least one waypoint");
  return p;
}

}  // namespace demoplan
