#include "core/model/robot_model.h"

#include <console_bridge/console.h>
#include <tinyxml.h>
#include <urdf_parser/urdf_parser.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <mutex>
#include <set>
#include <sstream>

#include "core/error.h"
#include "core/io/one_line.h"
#include "core/model/xml_text.h"

namespace demoplan {

namespace fs = std::filesystem;

int RobotModel::link_index(const std::string& n) const {
  for (size_t i = 0; i < links.size(); ++i)
    if (links[i].name == n) return static_cast<int>(i);
  return -1;
}

int RobotModel::joint_index(const std::string& n) const {
  for (size_t i = 0; i < joints.size(); ++i)
    if (joints[i].name == n) return static_cast<int>(i);
  return -1;
}

std::vector<const Joint*> RobotModel::configuration_joints() const {
  std::vector<const Joint*> out(nq, nullptr);
  for (const auto& j : joints)
    if (j.q_index >= 0) out[j.q_index] = &j;
  return out;
}

Eigen::VectorXd RobotModel::lower_limits() const {
  Eigen::VectorXd v(nq);
  for (const auto& j : joints)
    if (j.q_index >= 0) v[j.q_index] = j.limits.lower;
  return v;
}

Eigen::VectorXd RobotModel::upper_limits() const {
  Eigen::VectorXd v(nq);
  for (const auto& j : joints)
    if (j.q_index >= 0) v[j.q_index] = j.limits.upper;
  return v;
}

bool RobotModel::within_limits(const Eigen::VectorXd& q, double tol) const {
  if (q.size() != nq || !q.allFinite()) return false;
  for (const auto& j : joints) {
    if (j.q_index < 0) continue;
    if (q[j.q_index] < j.limits.lower - tol || q[j.q_index] > j.limits.upper + tol) return false;
  }
  return true;
}

void RobotModel::enforce_mimic(Eigen::VectorXd& q) const {
  for (const auto& j : joints) {
    if (j.q_index < 0 || !j.mimic) continue;
    const Joint& m = joints[j.mimic->joint];
    q[j.q_index] = j.mimic->multiplier * q[m.q_index] + j.mimic->offset;
  }
}

std::vector<int> RobotModel::rigid_bodies() const {
  std::vector<int> body(links.size());
  for (size_t i = 0; i < links.size(); ++i) {  // parents come first
    const int pj = links[i].parent_joint;
    body[i] = (pj >= 0 && joints[pj].type == JointType::Fixed) ? body[joints[pj].parent_link]
                                                                : static_cast<int>(i);
  }
  return body;
}

std::vector<int> RobotModel::subtree_links(int link) const {
  std::vector<int> out, stack{link};
  while (!stack.empty()) {
    const int l = stack.back();
    stack.pop_back();
    out.push_back(l);
    for (int j : links[l].child_joints) stack.push_back(joints[j].child_link);
  }
  return out;
}

namespace {

// urdfdom reports parse errors through console_bridge; keep the last one for our message.
class CapturingHandler : public console_bridge::OutputHandler {
public:
  // urdfdom logs the low-level cause first ("Unable to parse component [nan]"), then where it
  // was ("... of joint [j]"), then generic follow-ups: keep them all, in order, on one line.
  void log(const std::string& text, console_bridge::LogLevel level, const char*, int) override {
    if (level < console_bridge::CONSOLE_BRIDGE_LOG_ERROR) return;
    std::string line = text;
    std::replace(line.begin(), line.end(), '\n', ' ');
    if (errors.find(line) == std::string::npos) errors += (errors.empty() ? "" : "; ") + line;
  }
  std::string errors;
};

Pose to_pose(const urdf::Pose& p) {
  double x, y, z, w;
  p.rotation.getQuaternion(x, y, z, w);
  return pose_from_xyz_quat({p.position.x, p.position.y, p.position.z},
                            Eigen::Quaterniond(w, x, y, z));
}

bool finite(const urdf::Pose& p) {
  double x, y, z, w;
  p.rotation.getQuaternion(x, y, z, w);
  return std::isfinite(p.position.x) && std::isfinite(p.position.y) &&
         std::isfinite(p.position.z) && std::isfinite(x) && std::isfinite(y) && std::isfinite(z) &&
         std::isfinite(w);
}

class UrdfBuilder {
public:
  static constexpr int kMaxTreeDepth = 1000;

  UrdfBuilder(const std::string& source, const UrdfOptions& options)
      : source_(source), options_(options), dir_(fs::absolute(fs::path(source)).parent_path()) {}

  RobotModel build(const urdf::ModelInterface& urdf) {
    model_.name = urdf.getName();
    model_.urdf_path = source_;
    auto root = urdf.getRoot();
    if (!root) fail("robot", "has no root link");
    add_link(*root, -1);
    for (auto& j : model_.joints) resolve_mimic(j, urdf);
    return std::move(model_);
  }

private:
  [[noreturn]] void fail(const std::string& field, const std::string& reason) const {
    throw InputError(source_, one_line(field), one_line(reason));
  }

  void add_link(const urdf::Link& ul, int parent_joint, int depth = 0) {
    // Recursion, one level per link down the tree: bounded, so that neither a malformed model
    // nor a very long chain can overflow the stack.
    if (depth > kMaxTreeDepth)
      fail("link '" + ul.name + "'", "the kinematic tree is deeper than " + std::to_string(kMaxTreeDepth) + " links");
    const int index = static_cast<int>(model_.links.size());
    model_.links.push_back({});
    {
      Link& link = model_.links.back();
      link.name = ul.name;
      link.parent_joint = parent_joint;
    }
    const std::string where = "link '" + ul.name + "'";
    for (const auto& v : ul.visual_array) {
      if (!v || !v->geometry) continue;
      auto g = make_geometry(*v->geometry, v->origin, where + " visual", options_.load_visual_meshes);
      if (v->material) {
        const auto& c = v->material->color;
        g.color = {c.r, c.g, c.b, c.a};
      }
      model_.links[index].visuals.push_back(std::move(g));
    }
    for (const auto& c : ul.collision_array) {
      if (!c || !c->geometry) continue;
      model_.links[index].collisions.push_back(
          make_geometry(*c->geometry, c->origin, where + " collision", true));
    }
    for (const auto& uj : ul.child_joints) {
      const int ji = add_joint(*uj, index);
      model_.links[index].child_joints.push_back(ji);
      auto child = std::find_if(ul.child_links.begin(), ul.child_links.end(),
                                [&](const auto& l) { return l->name == uj->child_link_name; });
      if (child == ul.child_links.end()) fail("joint '" + uj->name + "'", "child link not found");
      model_.joints[ji].child_link = static_cast<int>(model_.links.size());
      add_link(**child, ji, depth + 1);
    }
  }

  int add_joint(const urdf::Joint& uj, int parent_link) {
    const std::string where = "joint '" + uj.name + "'";
    Joint j;
    j.name = uj.name;
    j.parent_link = parent_link;
    if (!finite(uj.parent_to_joint_origin_transform)) fail(where + " origin", "not a finite number");
    j.origin = to_pose(uj.parent_to_joint_origin_transform);
    const Eigen::Vector3d axis(uj.axis.x, uj.axis.y, uj.axis.z);
    switch (uj.type) {
      case urdf::Joint::FIXED: j.type = JointType::Fixed; break;
      case urdf::Joint::REVOLUTE: j.type = JointType::Revolute; break;
      case urdf::Joint::CONTINUOUS: j.type = JointType::Continuous; break;
      case urdf::Joint::PRISMATIC: j.type = JointType::Prismatic; break;
      case urdf::Joint::FLOATING:
      case urdf::Joint::PLANAR:
        fail(where + " type", "floating and planar joints are not supported; model a mobile base "
                              "as two prismatic joints and a revolute joint");
      default: fail(where + " type", "unknown joint type");
    }
    if (j.type != JointType::Fixed) {
      if (!axis.allFinite() || axis.norm() < 1e-9) fail(where + " axis", "must be a non-zero vector");
      j.axis = axis.normalized();
      j.q_index = model_.nq++;
      if (j.type == JointType::Continuous) {
        j.limits.lower = -std::numeric_limits<double>::infinity();
        j.limits.upper = std::numeric_limits<double>::infinity();
      }
      if (uj.limits) {
        const auto& l = *uj.limits;
        if (!std::isfinite(l.velocity) || !std::isfinite(l.effort) || l.velocity < 0 || l.effort < 0)
          fail(where + " limit", "velocity and effort must be finite and >= 0");
        j.limits.velocity = l.velocity;
        j.limits.effort = l.effort;
        if (j.type != JointType::Continuous) {
          if (!std::isfinite(l.lower) || !std::isfinite(l.upper) || l.lower > l.upper)
            fail(where + " limit", "lower and upper must be finite with lower <= upper");
          j.limits.lower = l.lower;
          j.limits.upper = l.upper;
        }
      } else if (j.type != JointType::Continuous) {
        fail(where + " limit", "revolute and prismatic joints need position limits");
      }
    }
    model_.joints.push_back(std::move(j));
    return static_cast<int>(model_.joints.size()) - 1;
  }

  void resolve_mimic(Joint& j, const urdf::ModelInterface& urdf) {
    auto uj = urdf.getJoint(j.name);
    if (!uj || !uj->mimic || j.q_index < 0) return;
    const int target = model_.joint_index(uj->mimic->joint_name);
    if (target < 0 || model_.joints[target].q_index < 0)
      fail("joint '" + j.name + "' mimic", "mimicked joint '" + uj->mimic->joint_name +
                                               "' does not exist or is fixed");
    if (!std::isfinite(uj->mimic->multiplier) || !std::isfinite(uj->mimic->offset))
      fail("joint '" + j.name + "' mimic", "multiplier and offset must be finite");
    j.mimic = Mimic{target, uj->mimic->multiplier, uj->mimic->offset};
  }

  std::string resolve_mesh_path(const std::string& uri, const std::string& where) const {
    static const std::string package = "package://", file = "file://";
    if (uri.rfind(package, 0) == 0) {
      const std::string rest = uri.substr(package.size());
      for (const auto& dir : options_.package_paths) {
        const fs::path p = fs::absolute(fs::path(dir) / rest);
        if (fs::exists(p)) return p.lexically_normal().string();
      }
      fail(where + " mesh '" + uri + "'", "not found in any package path");
    }
    fs::path p = uri.rfind(file, 0) == 0 ? fs::path(uri.substr(file.size())) : fs::path(uri);
    if (p.is_relative()) p = dir_ / p;
    p = p.lexically_normal();
    if (!fs::exists(p)) fail(where + " mesh '" + uri + "'", "file not found: " + p.string());
    return p.string();
  }

  Geometry make_geometry(const urdf::Geometry& ug, const urdf::Pose& origin,
                         const std::string& where, bool load_mesh_data) {
    Geometry g;
    if (!finite(origin)) fail(where + " origin", "not a finite number");
    g.origin = to_pose(origin);
    switch (ug.type) {
      case urdf::Geometry::BOX: {
        const auto& b = static_cast<const urdf::Box&>(ug);
        const Eigen::Vector3d size(b.dim.x, b.dim.y, b.dim.z);
        if (!size.allFinite() || (size.array() <= 0).any())
          fail(where + " box size", "must be three positive numbers");
        g.shape = BoxShape{size};
        break;
      }
      case urdf::Geometry::CYLINDER: {
        const auto& c = static_cast<const urdf::Cylinder&>(ug);
        if (!(c.radius > 0) || !(c.length > 0) || !std::isfinite(c.radius) || !std::isfinite(c.length))
          fail(where + " cylinder", "radius and length must be positive");
        g.shape = CylinderShape{c.radius, c.length};
        break;
      }
      case urdf::Geometry::SPHERE: {
        const auto& s = static_cast<const urdf::Sphere&>(ug);
        if (!(s.radius > 0) || !std::isfinite(s.radius)) fail(where + " sphere", "radius must be positive");
        g.shape = SphereShape{s.radius};
        break;
      }
      case urdf::Geometry::MESH: {
        const auto& m = static_cast<const urdf::Mesh&>(ug);
        MeshShape ms;
        ms.path = resolve_mesh_path(m.filename, where);
        ms.scale = {m.scale.x, m.scale.y, m.scale.z};
        if (!ms.scale.allFinite() || (ms.scale.array() == 0).any())
          fail(where + " mesh scale", "must be three non-zero numbers");
        if (load_mesh_data) {
          try {
            ms.mesh = options_.mesh_cache ? options_.mesh_cache->get(ms.path) : load_mesh(ms.path);
          } catch (const InputError& e) {
            fail(where + " mesh '" + m.filename + "'", e.what());
          }
        }
        g.shape = std::move(ms);
        break;
      }
      default: fail(where, "unsupported geometry type");
    }
    return g;
  }

  std::string source_;
  const UrdfOptions& options_;
  fs::path dir_;
  RobotModel model_;
};

std::mutex console_mutex;  // console_bridge's output handler is process-wide

// Why the joints do not form a tree: a link that is the child of two joints, or a cycle of joints
// (its links, parent first: "a -> b -> a"); "" when they form one. urdfdom only says "No root
// link found" for a cycle, and accepts a link with two parents, building a model whose links
// hold each other (found by fuzz_urdf: the builder below recursed until the stack overflowed).
std::string tree_error(const std::string& xml) {
  TiXmlDocument doc;
  const std::string text = padded_for_tinyxml(xml);
  doc.Parse(text.c_str());
  const TiXmlElement* robot = doc.Error() ? nullptr : doc.FirstChildElement("robot");
  if (!robot) return {};
  std::map<std::string, std::string> parent_of;  // child link -> parent link
  std::map<std::string, std::string> joint_of;   // child link -> its joint
  for (auto* j = robot->FirstChildElement("joint"); j; j = j->NextSiblingElement("joint")) {
    const TiXmlElement* p = j->FirstChildElement("parent");
    const TiXmlElement* c = j->FirstChildElement("child");
    if (!p || !c || !p->Attribute("link") || !c->Attribute("link")) continue;
    const std::string child = c->Attribute("link"), name = j->Attribute("name") ? j->Attribute("name") : "";
    if (auto [it, inserted] = joint_of.emplace(child, name); !inserted)
      return "link '" + child + "' is the child of two joints ('" + it->second + "' and '" + name +
             "'); a URDF must be a tree";
    parent_of[child] = p->Attribute("link");
  }
  for (const auto& entry : parent_of) {
    std::set<std::string> seen;
    std::string link = entry.first;
    while (parent_of.count(link) && seen.insert(link).second) link = parent_of.at(link);
    if (!seen.count(link)) continue;  // reached a root
    std::string chain = link;         // on the cycle: walk it once more, child to parent
    for (std::string l = parent_of.at(link); ; l = parent_of.at(l)) {
      chain = l + " -> " + chain;
      if (l == link) break;
    }
    return "the joints form a cycle (" + chain + "); a URDF must be a tree";
  }
  return {};
}

}  // namespace

RobotModel parse_urdf(const std::string& xml, const std::string& source_path,
                      const UrdfOptions& options) {
  // Joints that do not form a tree are refused before urdfdom sees them: urdfdom refuses a cycle
  // too ("No root link found") but leaks its links, which hold each other, and accepts a link with
  // two parents (found by fuzz_urdf).
  if (const std::string error = tree_error(xml); !error.empty())
    throw InputError(source_path, "URDF", one_line(error));
  urdf::ModelInterfaceSharedPtr urdf;
  {
    std::lock_guard lock(console_mutex);
    CapturingHandler handler;
    console_bridge::useOutputHandler(&handler);
    try {
      urdf = urdf::parseURDF(padded_for_tinyxml(xml));
    } catch (const std::exception& e) {
      if (handler.errors.empty()) handler.errors = e.what();
    }
    console_bridge::restorePreviousOutputHandler();
    // urdfdom drops an element it cannot parse and still returns a model: any logged error fails.
    if (!urdf || !handler.errors.empty()) {
      throw InputError(source_path, "URDF", handler.errors.empty() ? "not a valid URDF" : one_line(handler.errors));
    }
  }
  return UrdfBuilder(source_path, options).build(*urdf);
}

RobotModel load_urdf(const std::string& path, const UrdfOptions& options) {
  std::ifstream in(path);
  if (!in) throw InputError(path, "", "cannot open URDF file");
  std::stringstream ss;
  ss << in.rdbuf();
  return parse_urdf(ss.str(), path, options);
}

}  // namespace demoplan
