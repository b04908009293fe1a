#include "core/model/srdf.h"

#include <tinyxml.h>

#include <cmath>
#include <fstream>
#include <sstream>

#include "core/error.h"
#include "core/io/one_line.h"
#include "core/model/xml_text.h"

namespace demoplan {

std::vector<std::vector<Eigen::Vector3d>> ContactSurface::polygon_vertices() const {
  std::vector<std::vector<Eigen::Vector3d>> out;
  for (const auto& poly : polygons) {
    auto& v = out.emplace_back();
    for (int i : poly) v.push_back(points[i]);
  }
  return out;
}

const GraspFrame* Srdf::gripper(const std::string& n) const {
  for (const auto& g : grippers)
    if (g.name == n) return &g;
  return nullptr;
}

const GraspFrame* Srdf::handle(const std::string& n) const {
  for (const auto& h : handles)
    if (h.name == n) return &h;
  return nullptr;
}

bool Srdf::collision_disabled(const std::string& a, const std::string& b) const {
  for (const auto& [l1, l2] : disabled_collisions)
    if ((l1 == a && l2 == b) || (l1 == b && l2 == a)) return true;
  return false;
}

namespace {

class SrdfParser {
public:
  explicit SrdfParser(std::string source) : source_(std::move(source)) {}

  Srdf parse(const std::string& xml) {
    TiXmlDocument doc;
    const std::string text = padded_for_tinyxml(xml);
    doc.Parse(text.c_str());
    if (doc.Error()) {
      fail(doc.ErrorRow() > 0 ? "line " + std::to_string(doc.ErrorRow()) : "", std::string("XML error: ") + doc.ErrorDesc());
    }
    const TiXmlElement* robot = doc.RootElement();
    if (!robot || std::string(robot->Value()) != "robot") fail("", "root element must be <robot>");
    Srdf srdf;
    srdf.path = source_;
    if (const char* n = robot->Attribute("name")) srdf.robot_name = n;
    for (auto* e = robot->FirstChildElement(); e; e = e->NextSiblingElement()) {
      const std::string tag = e->Value();
      if (tag == "gripper") srdf.grippers.push_back(grasp_frame(*e, "gripper"));
      else if (tag == "handle") srdf.handles.push_back(grasp_frame(*e, "handle"));
      else if (tag == "contact") srdf.contacts.push_back(contact(*e));
      else if (tag == "disable_collisions") {
        const std::string where = "disable_collisions (line " + std::to_string(e->Row()) + ")";
        srdf.disabled_collisions.emplace_back(attribute(*e, "link1", where),
                                              attribute(*e, "link2", where));
      }
    }
    return srdf;
  }

private:
  [[noreturn]] void fail(const std::string& field, const std::string& reason) const {
    throw InputError(source_, one_line(field), one_line(reason));
  }

  std::string attribute(const TiXmlElement& e, const char* name, const std::string& where) const {
    const char* v = e.Attribute(name);
    if (!v || !*v) fail(where, std::string("missing attribute '") + name + "'");
    return v;
  }

  std::vector<double> numbers(const TiXmlElement* e, const std::string& where) const {
    std::vector<double> out;
    if (!e || !e->GetText()) return out;
    std::istringstream in(e->GetText());
    std::string token;
    while (in >> token) {
      char* end = nullptr;
      const double v = std::strtod(token.c_str(), &end);
      if (end == token.c_str() || *end != '\0') fail(where, "'" + token + "' is not a number");
      if (!std::isfinite(v)) fail(where, "'" + token + "' is not a finite number");
      out.push_back(v);
    }
    return out;
  }

  std::string child_link(const TiXmlElement& e, const std::string& where) const {
    const TiXmlElement* link = e.FirstChildElement("link");
    if (!link) fail(where, "missing <link>");
    return attribute(*link, "name", where + " link");
  }

  GraspFrame grasp_frame(const TiXmlElement& e, const std::string& kind) {
    GraspFrame f;
    f.name = attribute(e, "name", kind + " (line " + std::to_string(e.Row()) + ")");
    const std::string where = kind + " '" + f.name + "'";
    const char* clearance = e.Attribute("clearance");
    if (clearance) {
      char* end = nullptr;
      f.clearance = std::strtod(clearance, &end);
      if (end == clearance || *end != '\0' || !std::isfinite(f.clearance) || f.clearance < 0)
        fail(where + " clearance", "must be a number >= 0");
    }
    f.link = child_link(e, where);
    const auto p = numbers(e.FirstChildElement("position"), where + " position");
    if (p.size() != 7) fail(where + " position", "needs 7 numbers: x y z qw qx qy qz");
    const Eigen::Quaterniond q(p[3], p[4], p[5], p[6]);
    if (std::abs(q.norm() - 1.0) > 1e-3) fail(where + " position", "quaternion is not unit length");
    f.pose = pose_from_xyz_quat({p[0], p[1], p[2]}, q);
    return f;
  }

  ContactSurface contact(const TiXmlElement& e) {
    ContactSurface c;
    c.name = attribute(e, "name", "contact (line " + std::to_string(e.Row()) + ")");
    const std::string where = "contact '" + c.name + "'";
    c.link = child_link(e, where);
    const auto pts = numbers(e.FirstChildElement("point"), where + " point");
    if (pts.empty() || pts.size() % 3 != 0) fail(where + " point", "needs a multiple of 3 numbers");
    for (size_t i = 0; i < pts.size(); i += 3) c.points.emplace_back(pts[i], pts[i + 1], pts[i + 2]);
    const auto shape = numbers(e.FirstChildElement("shape"), where + " shape");
    for (size_t i = 0; i < shape.size();) {
      const double count = shape[i];
      if (!(count >= 3) || count != std::floor(count) || count > static_cast<double>(shape.size() - i - 1))
        fail(where + " shape", "each polygon is N >= 3 followed by N vertex indices");
      const int n = static_cast<int>(count);
      if (i + 1 + static_cast<size_t>(n) > shape.size())
        fail(where + " shape", "each polygon is N >= 3 followed by N vertex indices");
      auto& poly = c.polygons.emplace_back();
      for (int k = 0; k < n; ++k) {
        const double idx = shape[i + 1 + k];
        if (idx < 0 || idx >= static_cast<double>(c.points.size()) || idx != std::floor(idx))
          fail(where + " shape", "vertex index " + std::to_string(idx) + " out of range");
        poly.push_back(static_cast<int>(idx));
      }
      i += 1 + n;
    }
    if (c.polygons.empty()) fail(where + " shape", "has no polygon");
    return c;
  }

  std::string source_;
};

}  // namespace

Srdf parse_srdf(const std::string& xml, const std::string& source_path) {
  return SrdfParser(source_path).parse(xml);
}

Srdf load_srdf(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw InputError(path, "", "cannot open SRDF file");
  std::stringstream ss;
  ss << in.rdbuf();
  return parse_srdf(ss.str(), path);
}

}  // namespace demoplan
