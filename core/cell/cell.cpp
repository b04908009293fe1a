#include "core/cell/cell.h"

#include <cmath>
#include <filesystem>
#include <set>

#include "core/error.h"
#include "core/io/stored_path.h"

namespace demoplan {

int Cell::part_index(const std::string& n) const {
  for (size_t i = 0; i < parts.size(); ++i)
    if (parts[i].name == n) return static_cast<int>(i);
  return -1;
}

namespace {

Json vec(const Eigen::Vector3d& v) { return Json::array({v.x(), v.y(), v.z()}); }

Json pose_to_json(const Pose& p) {
  return Json{{"xyz", vec(p.translation())}, {"rpy", vec(rpy_from_rotation(p.linear()))}};
}

Eigen::Vector3d vector3(const JsonField& f) {
  const Eigen::VectorXd v = f.vector();
  if (v.size() != 3) f.fail("must have 3 numbers");
  return v;
}

Pose pose_from(const JsonField& f) {
  if (!f.value().is_object()) f.fail("must be an object {\"xyz\": [x, y, z], \"rpy\": [roll, pitch, yaw]}");
  const Eigen::Vector3d xyz = f.has("xyz") ? vector3(f["xyz"]) : Eigen::Vector3d::Zero();
  const Eigen::Vector3d rpy = f.has("rpy") ? vector3(f["rpy"]) : Eigen::Vector3d::Zero();
  return pose_from_xyz_rpy(xyz, rpy);
}

double positive(const JsonField& f) {
  const double v = f.number();
  if (!(v > 0)) f.fail("must be > 0");
  return v;
}

Eigen::Vector4d color_from(const JsonField& f) {
  const Eigen::VectorXd c = f.vector();
  if (c.size() != 4 || (c.array() < 0).any() || (c.array() > 1).any()) f.fail("must be 4 numbers (r, g, b, a) in 0..1");
  return c;
}

Json polygons_to_json(const std::vector<Polygon3>& polygons) {
  Json out = Json::array();
  for (const auto& poly : polygons) {
    Json p = Json::array();
    for (const auto& v : poly) p.push_back(vec(v));
    out.push_back(p);
  }
  return out;
}

std::vector<Polygon3> polygons_from(const JsonField& f) {
  if (!f.value().is_array()) f.fail("must be \"auto\" or a list of polygons, each a list of [x, y, z] points");
  std::vector<Polygon3> out;
  for (size_t i = 0; i < f.size(); ++i) {
    const JsonField poly = f[i];
    if (!poly.value().is_array() || poly.size() < 3) poly.fail("a polygon needs at least 3 points");
    Polygon3& p = out.emplace_back();
    for (size_t k = 0; k < poly.size(); ++k) p.push_back(vector3(poly[k]));
  }
  return out;
}

bool is_auto(const JsonField& parent, const std::string& key) {
  return !parent.has(key) || (parent[key].value().is_string() && parent[key].string() == "auto");
}

void unique_name(std::set<std::string>& seen, const JsonField& f, const std::string& name) {
  if (name.empty()) f.fail("must not be empty");
  if (!seen.insert(name).second) f.fail("'" + name + "' is used twice");
}

CellRobot robot_from(const JsonField& r, const std::string& file) {
  CellRobot robot;
  if (r.has("bundled") == r.has("urdf")) r.fail("give either \"bundled\" (a robot name) or \"urdf\" and \"srdf\"");
  if (r.has("bundled")) {
    robot.bundled = r["bundled"].string();
  } else {
    robot.urdf = from_stored(r["urdf"].string(), file);
    robot.srdf = from_stored(r["srdf"].string(), file);
  }
  if (r.has("mobile")) robot.mobile = r["mobile"].boolean();
  if (r.has("initial_configuration")) robot.initial_configuration = r["initial_configuration"].vector();
  if (r.has("base")) robot.base = pose_from(r["base"]);
  return robot;
}

CellFurniture furniture_from(const JsonField& f, const std::string& file) {
  CellFurniture out;
  out.name = f["name"].string();
  const int shapes = f.has("box") + f.has("cylinder") + f.has("mesh") + f.has("urdf");
  if (shapes != 1) f.fail("needs exactly one of \"box\", \"cylinder\", \"mesh\", \"urdf\"");
  if (f.has("box")) {
    out.kind = CellFurniture::Kind::Box;
    out.box = vector3(f["box"]);
    if ((out.box.array() <= 0).any()) f["box"].fail("sizes must be > 0");
  } else if (f.has("cylinder")) {
    out.kind = CellFurniture::Kind::Cylinder;
    out.radius = positive(f["cylinder"]["radius"]);
    out.length = positive(f["cylinder"]["length"]);
  } else if (f.has("mesh")) {
    out.kind = CellFurniture::Kind::Mesh;
    out.file = from_stored(f["mesh"].string(), file);
    if (f.has("scale")) out.scale = positive(f["scale"]);
  } else {
    out.kind = CellFurniture::Kind::Urdf;
    out.file = from_stored(f["urdf"].string(), file);
    if (f.has("srdf")) out.srdf = from_stored(f["srdf"].string(), file);
  }
  if (f.has("pose")) out.pose = pose_from(f["pose"]);
  out.auto_supports = is_auto(f, "supports");
  if (!out.auto_supports) out.supports = polygons_from(f["supports"]);
  if (f.has("min_support_area")) out.min_support_area = positive(f["min_support_area"]);
  if (f.has("color")) out.color = color_from(f["color"]);
  return out;
}

CellPart part_from(const JsonField& p, const std::string& file) {
  CellPart out;
  out.name = p["name"].string();
  out.mesh = from_stored(p["mesh"].string(), file);
  if (p.has("scale")) out.scale = positive(p["scale"]);
  if (p.has("pose")) out.pose = pose_from(p["pose"]);
  out.auto_contacts = is_auto(p, "contacts");
  if (!out.auto_contacts) out.contacts = polygons_from(p["contacts"]);
  out.auto_handles = is_auto(p, "handles");
  if (!out.auto_handles) {
    const JsonField hs = p["handles"];
    if (!hs.value().is_array()) hs.fail("must be \"auto\" or a list of handles");
    std::set<std::string> names;
    for (size_t i = 0; i < hs.size(); ++i) {
      GraspFrame h;
      h.name = hs[i]["name"].string();
      unique_name(names, hs[i]["name"], h.name);
      h.link = "base_link";
      h.pose = pose_from(hs[i]["pose"]);
      h.clearance = positive(hs[i]["clearance"]);
      out.handles.push_back(h);
    }
  }
  if (p.has("markers")) {
    const JsonField ms = p["markers"];
    for (size_t i = 0; i < ms.size(); ++i) {
      CellMarker m;
      m.id = ms[i]["id"].integer();
      if (m.id < 0) ms[i]["id"].fail("must be >= 0");
      m.size = positive(ms[i]["size"]);
      if (ms[i].has("pose")) m.pose = pose_from(ms[i]["pose"]);
      out.markers.push_back(m);
    }
  }
  if (p.has("color")) out.color = color_from(p["color"]);
  return out;
}

}  // namespace

Json cell_to_json(const Cell& c, const std::string& file) {
  Json robot = Json::object();
  if (!c.robot.bundled.empty()) {
    robot["bundled"] = c.robot.bundled;
  } else {
    robot["urdf"] = to_stored(c.robot.urdf, file);
    robot["srdf"] = to_stored(c.robot.srdf, file);
    robot["mobile"] = c.robot.mobile;
  }
  if (c.robot.initial_configuration.size() > 0)
    robot["initial_configuration"] = std::vector<double>(c.robot.initial_configuration.data(),
                                                         c.robot.initial_configuration.data() + c.robot.initial_configuration.size());
  robot["base"] = pose_to_json(c.robot.base);
  Json furniture = Json::array();
  for (const auto& f : c.furniture) {
    Json j{{"name", f.name}};
    switch (f.kind) {
      case CellFurniture::Kind::Box: j["box"] = vec(f.box); break;
      case CellFurniture::Kind::Cylinder: j["cylinder"] = {{"radius", f.radius}, {"length", f.length}}; break;
      case CellFurniture::Kind::Mesh: j["mesh"] = to_stored(f.file, file), j["scale"] = f.scale; break;
      case CellFurniture::Kind::Urdf:
        j["urdf"] = to_stored(f.file, file);
        if (!f.srdf.empty()) j["srdf"] = to_stored(f.srdf, file);
        break;
    }
    j["pose"] = pose_to_json(f.pose);
    j["supports"] = f.auto_supports ? Json("auto") : polygons_to_json(f.supports);
    j["min_support_area"] = f.min_support_area;
    j["color"] = {f.color[0], f.color[1], f.color[2], f.color[3]};
    furniture.push_back(j);
  }
  Json parts = Json::array();
  for (const auto& p : c.parts) {
    Json j{{"name", p.name}, {"mesh", to_stored(p.mesh, file)}, {"scale", p.scale}, {"pose", pose_to_json(p.pose)}};
    j["contacts"] = p.auto_contacts ? Json("auto") : polygons_to_json(p.contacts);
    if (p.auto_handles) {
      j["handles"] = "auto";
    } else {
      Json hs = Json::array();
      for (const auto& h : p.handles) hs.push_back({{"name", h.name}, {"pose", pose_to_json(h.pose)}, {"clearance", h.clearance}});
      j["handles"] = hs;
    }
    Json ms = Json::array();
    for (const auto& m : p.markers) ms.push_back({{"id", m.id}, {"size", m.size}, {"pose", pose_to_json(m.pose)}});
    j["markers"] = ms;
    j["color"] = {p.color[0], p.color[1], p.color[2], p.color[3]};
    parts.push_back(j);
  }
  Json package_paths = Json::array();
  for (const auto& p : c.package_paths) package_paths.push_back(to_stored(p, file));
  return Json{{"format", kCellFormat},
              {"version", kCellVersion},
              {"units", "metres, radians; poses {xyz, rpy}; paths relative to this file"},
              {"name", c.name},
              {"package_paths", package_paths},
              {"robot", robot},
              {"furniture", furniture},
              {"parts", parts},
              {"marker_dictionary", c.marker_dictionary},
              {"grasping", {{"palm_clearance", c.grasping.palm_clearance}, {"max_handles", c.grasping.max_handles}}}};
}

Cell cell_from_json(const Json& json, const std::string& file) {
  const JsonField root(json, file);
  check_format(root, kCellFormat, kCellVersion, "cell");
  Cell c;
  c.file = std::filesystem::absolute(file).lexically_normal().string();
  c.name = root.has("name") ? root["name"].string() : "";
  if (root.has("package_paths"))
    for (size_t i = 0; i < root["package_paths"].size(); ++i)
      c.package_paths.push_back(from_stored(root["package_paths"][i].string(), file));
  c.robot = robot_from(root["robot"], file);
  std::set<std::string> names;
  if (root.has("furniture"))
    for (size_t i = 0; i < root["furniture"].size(); ++i) {
      c.furniture.push_back(furniture_from(root["furniture"][i], file));
      unique_name(names, root["furniture"][i]["name"], c.furniture.back().name);
    }
  const JsonField parts = root["parts"];
  for (size_t i = 0; i < parts.size(); ++i) {
    c.parts.push_back(part_from(parts[i], file));
    unique_name(names, parts[i]["name"], c.parts.back().name);
  }
  if (root.has("marker_dictionary")) c.marker_dictionary = root["marker_dictionary"].string();
  if (root.has("grasping")) {
    const JsonField g = root["grasping"];
    if (g.has("palm_clearance")) {
      c.grasping.palm_clearance = g["palm_clearance"].number();
      if (c.grasping.palm_clearance < 0) g["palm_clearance"].fail("must be >= 0");
    }
    if (g.has("max_handles")) {
      c.grasping.max_handles = g["max_handles"].integer();
      if (c.grasping.max_handles < 1) g["max_handles"].fail("must be >= 1");
    }
  }
  return c;
}

Cell load_cell(const std::string& file) { return cell_from_json(read_json_file(file), file); }

void save_cell(const std::string& file, const Cell& cell) { write_json_file_atomic(file, cell_to_json(cell, file), 1); }

}  // namespace demoplan
