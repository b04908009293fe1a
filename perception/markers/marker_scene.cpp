#include "perception/markers/marker_scene.h"

#include <set>

#include "core/error.h"
#include "perception/io/pose_json.h"
#include "perception/markers/marker_dictionary.h"

namespace demoplan::perception {

namespace {
constexpr const char* kFormat = "demoplan-marker-scene";
constexpr int kVersion = 1;
}  // namespace

bool MarkerScene::find_marker(int id, int& object, int& marker) const {
  for (size_t o = 0; o < objects.size(); ++o)
    for (size_t m = 0; m < objects[o].markers.size(); ++m)
      if (objects[o].markers[m].id == id) {
        object = static_cast<int>(o);
        marker = static_cast<int>(m);
        return true;
      }
  return false;
}

std::vector<std::string> MarkerScene::planning_object_ids() const {
  std::vector<std::string> ids;
  for (const auto& o : objects)
    if (o.planning) ids.push_back(o.id);
  return ids;
}

Eigen::AlignedBox3d marker_extent(const MarkedObject& object) {
  if (object.box) return Eigen::AlignedBox3d(-*object.box / 2, *object.box / 2);
  Eigen::AlignedBox3d box;
  for (const auto& m : object.markers) {
    const double h = m.size / 2;
    for (double x : {-h, h})
      for (double y : {-h, h}) box.extend(m.object_T_marker * Eigen::Vector3d(x, y, 0));
  }
  if (box.isEmpty()) box = Eigen::AlignedBox3d(Eigen::Vector3d::Constant(-0.05), Eigen::Vector3d::Constant(0.05));
  return box;
}

MarkerScene load_marker_scene(const std::string& path) {
  const Json json = read_json_file(path);
  const JsonField root(json, path);
  check_format(root, kFormat, kVersion);
  MarkerScene s;
  s.task = root.has("task") ? root["task"].string() : "";
  s.robot = root.has("robot") ? root["robot"].string() : "";
  s.robot_pose = root.has("robot_pose") ? root["robot_pose"].integer() : 0;
  s.camera = root.has("camera") ? root["camera"].string() : "";
  s.cell = root.has("cell") ? root["cell"].string() : "";
  s.dictionary = root["dictionary"].string();
  if (!is_marker_dictionary(s.dictionary)) root["dictionary"].fail("unknown ArUco dictionary '" + s.dictionary + "'");
  const JsonField objects = root["objects"];
  if (objects.size() == 0) objects.fail("must name at least one object");
  std::set<int> used;
  std::set<std::string> names;
  for (size_t i = 0; i < objects.size(); ++i) {
    const JsonField o = objects[i];
    MarkedObject obj;
    obj.id = o["id"].string();
    if (!names.insert(obj.id).second) o["id"].fail("object '" + obj.id + "' is listed twice");
    obj.planning = o.has("planning") ? o["planning"].boolean() : true;
    const JsonField markers = o["markers"];
    for (size_t k = 0; k < markers.size(); ++k) {
      const JsonField m = markers[k];
      ObjectMarker mk;
      mk.id = m["id"].integer();
      if (mk.id < 0) m["id"].fail("must be >= 0");
      if (!used.insert(mk.id).second) m["id"].fail("marker id " + std::to_string(mk.id) + " is used twice");
      mk.size = m["size"].number();
      if (!(mk.size > 0)) m["size"].fail("must be > 0 (metres)");
      mk.object_T_marker = pose_from_json(m["object_T_marker"]);
      obj.markers.push_back(mk);
    }
    if (o.has("box")) {
      const JsonField box = o["box"];
      const Eigen::VectorXd size = box["size"].vector();
      if (size.size() != 3 || !(size.minCoeff() > 0)) box["size"].fail("must be three sizes > 0 (metres)");
      obj.box = size.head<3>();
      if (box.has("rgb")) {
        const Eigen::VectorXd rgb = box["rgb"].vector();
        if (rgb.size() != 3 || rgb.minCoeff() < 0 || rgb.maxCoeff() > 255) box["rgb"].fail("must be three values 0..255");
        obj.box_rgb = rgb.head<3>().array().round().cast<int>();
      }
    }
    s.objects.push_back(std::move(obj));
  }
  return s;
}

void save_marker_scene(const std::string& path, const MarkerScene& s) {
  Json objects = Json::array();
  for (const auto& o : s.objects) {
    Json markers = Json::array();
    for (const auto& m : o.markers)
      markers.push_back({{"id", m.id}, {"size", m.size}, {"object_T_marker", pose_to_json(m.object_T_marker)}});
    Json object{{"id", o.id}, {"planning", o.planning}, {"markers", markers}};
    if (o.box)
      object["box"] = {{"size", {o.box->x(), o.box->y(), o.box->z()}}, {"rgb", {o.box_rgb.x(), o.box_rgb.y(), o.box_rgb.z()}}};
    objects.push_back(object);
  }
  Json j{{"format", kFormat},
               {"version", kVersion},
               {"conventions", "object_T_marker: marker frame (OpenCV: origin at the centre, z out of the face) in "
                               "the object frame; t in metres, q = [qx, qy, qz, qw]; size = black square side, m"},
               {"task", s.task},
               {"robot", s.robot},
               {"robot_pose", s.robot_pose},
               {"camera", s.camera},
               {"dictionary", s.dictionary},
               {"objects", objects}};
  if (!s.cell.empty()) j["cell"] = s.cell;  // older readers ignore it
  write_json_file_atomic(path, j);
}

}  // namespace demoplan::perception
