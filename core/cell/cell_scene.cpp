#include "core/cell/cell_scene.h"

#include <algorithm>
#include <cmath>
#include <exception>
#include <filesystem>
#include <sstream>
#include <stdexcept>
#include <thread>

#include "core/cell/support_surfaces.h"
#include "core/demo/benchmark_scene.h"
#include "core/error.h"
#include "core/model/kinematics.h"
#include "core/model/mobile_base.h"
#include "core/parallel_for.h"
#include "core/part/resting_placements.h"

namespace demoplan {

namespace fs = std::filesystem;

namespace {

struct Triangles {
  std::vector<Eigen::Vector3d> vertices;
  std::vector<std::array<std::uint32_t, 3>> triangles;
};

// A collision geometry as triangles in its link's frame (spheres have no flat face: none).
Triangles triangles_of(const Geometry& g) {
  Triangles t;
  auto add = [&](std::uint32_t a, std::uint32_t b, std::uint32_t c) { t.triangles.push_back({a, b, c}); };
  if (const auto* b = std::get_if<BoxShape>(&g.shape)) {
    const Eigen::Vector3d h = b->size / 2;
    for (int i = 0; i < 8; ++i) t.vertices.emplace_back(i & 1 ? h.x() : -h.x(), i & 2 ? h.y() : -h.y(), i & 4 ? h.z() : -h.z());
    const int faces[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
    for (const auto& f : faces) add(f[0], f[1], f[2]), add(f[0], f[2], f[3]);
  } else if (const auto* c = std::get_if<CylinderShape>(&g.shape)) {
    const int n = 48;
    for (int i = 0; i < n; ++i) {
      const double a = 2 * M_PI * i / n;
      t.vertices.emplace_back(c->radius * std::cos(a), c->radius * std::sin(a), -c->length / 2);
      t.vertices.emplace_back(c->radius * std::cos(a), c->radius * std::sin(a), c->length / 2);
    }
    for (int i = 1; i + 1 < n; ++i) add(1, 2 * i + 1, 2 * i + 3), add(0, 2 * i + 2, 2 * i);
    for (int i = 0; i < n; ++i) {
      const std::uint32_t a = 2 * i, b = 2 * ((i + 1) % n);
      add(a, b, b + 1), add(a, b + 1, a + 1);
    }
  } else if (const auto* m = std::get_if<MeshShape>(&g.shape)) {
    for (const auto& v : m->mesh->vertices) t.vertices.push_back(v.cast<double>().cwiseProduct(m->scale));
    t.triangles = m->mesh->triangles;
  }
  for (auto& v : t.vertices) v = g.origin * v;
  return t;
}

std::shared_ptr<const TriangleMesh> mesh_of(const std::string& path, const CellSceneOptions& o) {
  return o.mesh_cache ? o.mesh_cache->get(path) : load_mesh(path);
}

// One rigid link holding one geometry.
RobotModel single_link(const std::string& name, const std::string& link, Geometry g) {
  RobotModel m;
  m.name = name;
  m.links.emplace_back();
  m.links[0].name = link;
  m.links[0].collisions.push_back(g);
  m.links[0].visuals.push_back(std::move(g));
  return m;
}

ContactSurface contact_surface(const std::string& name, const std::string& link, const std::vector<Polygon3>& polygons) {
  ContactSurface c;
  c.name = name;
  c.link = link;
  for (const auto& poly : polygons) {
    std::vector<int> idx;
    for (const auto& p : poly) {
      idx.push_back(static_cast<int>(c.points.size()));
      c.points.push_back(p);
    }
    c.polygons.push_back(std::move(idx));
  }
  return c;
}

SceneRobot cell_robot(const Cell& cell, const CellSceneOptions& o, const UrdfOptions& urdf_options) {
  const std::string field = "robot";
  SceneRobot robot;
  std::string urdf = cell.robot.urdf, srdf = cell.robot.srdf;
  robot.fixed_base = !cell.robot.mobile;
  if (!cell.robot.bundled.empty()) {
    const std::vector<std::string> known = list_benchmark_robots(o.data_dir);
    if (std::find(known.begin(), known.end(), cell.robot.bundled) == known.end()) {
      std::string list;
      for (const auto& k : known) list += (list.empty() ? "" : ", ") + k;
      throw InputError(cell.file, "robot.bundled", "no bundled robot '" + cell.robot.bundled + "' (bundled: " + list + ")");
    }
    const BenchmarkRobot b = load_benchmark_robot(o.data_dir, cell.robot.bundled);
    urdf = b.urdf, srdf = b.srdf;
    robot.fixed_base = b.fixed_base;
    robot.initial_configuration = b.initial_configuration;
    robot.name = b.name;
  }
  for (const auto& [path, key] : {std::pair{urdf, "robot.urdf"}, std::pair{srdf, "robot.srdf"}})
    if (!fs::is_regular_file(path)) throw InputError(cell.file, key, "no such file: " + path);
  robot.model = load_urdf(urdf, urdf_options);
  // A robot from disk said to be mobile must have the planar joints the planner moves it by.
  if (!robot.fixed_base && cell.robot.bundled.empty())
    if (const std::string problem = mobile_base_problem(robot.model, fs::path(urdf).filename().string()); !problem.empty())
      throw InputError(cell.file, "robot.mobile", problem);
  robot.srdf = load_srdf(srdf);
  if (robot.name.empty()) robot.name = robot.model.name;
  robot.base = cell.robot.base;
  if (cell.robot.initial_configuration.size() > 0) robot.initial_configuration = cell.robot.initial_configuration;
  if (robot.initial_configuration.size() == 0) {
    robot.initial_configuration = Eigen::VectorXd::Zero(robot.model.nq);
    const Eigen::VectorXd lo = robot.model.lower_limits(), hi = robot.model.upper_limits();
    for (int i = 0; i < robot.model.nq; ++i) robot.initial_configuration[i] = std::clamp(0.0, lo[i], hi[i]);
  }
  if (robot.initial_configuration.size() != robot.model.nq)
    throw InputError(cell.file, field + ".initial_configuration",
                     "has " + std::to_string(robot.initial_configuration.size()) + " entries, " + urdf + " has " +
                         std::to_string(robot.model.nq) + " joints");
  if (!robot.model.within_limits(robot.initial_configuration, 1e-9))
    throw InputError(cell.file, field + ".initial_configuration", "is outside the joint limits of " + urdf);
  if (robot.srdf.grippers.empty()) throw InputError(srdf, "gripper", "the robot has no gripper");
  robot.gripper_link = robot.model.link_index(robot.gripper().link);
  if (robot.gripper_link < 0)
    throw InputError(srdf, "gripper '" + robot.gripper().name + "' link", "link '" + robot.gripper().link + "' is not in " + urdf);
  return robot;
}

SceneFurniture cell_furniture(const Cell& cell, size_t index, const CellSceneOptions& o, const UrdfOptions& urdf_options,
                              int* supports) {
  const CellFurniture& f = cell.furniture[index];
  const std::string field = "furniture[" + std::to_string(index) + "]";
  SceneFurniture fu;
  fu.name = f.name;
  Geometry g;
  g.color = f.color;
  switch (f.kind) {
    case CellFurniture::Kind::Box: fu.kind = "box", g.shape = BoxShape{f.box}; break;
    case CellFurniture::Kind::Cylinder: fu.kind = "cylinder", g.shape = CylinderShape{f.radius, f.length}; break;
    case CellFurniture::Kind::Mesh:
      if (!fs::is_regular_file(f.file)) throw InputError(cell.file, field + ".mesh", "no such file: " + f.file);
      fu.kind = "mesh", g.shape = MeshShape{f.file, Eigen::Vector3d::Constant(f.scale), mesh_of(f.file, o)};
      break;
    case CellFurniture::Kind::Urdf:
      if (!fs::is_regular_file(f.file)) throw InputError(cell.file, field + ".urdf", "no such file: " + f.file);
      fu.kind = "urdf";
      break;
  }
  if (f.kind == CellFurniture::Kind::Urdf) {
    fu.model = load_urdf(f.file, urdf_options);
    if (fu.model.nq != 0) throw InputError(f.file, "", "furniture must have only fixed joints");
    if (!f.srdf.empty()) {
      if (!fs::is_regular_file(f.srdf)) throw InputError(cell.file, field + ".srdf", "no such file: " + f.srdf);
      fu.srdf = load_srdf(f.srdf);
      for (const auto& c : fu.srdf.contacts)
        if (fu.model.link_index(c.link) < 0)
          throw InputError(f.srdf, "contact '" + c.name + "' link", "link '" + c.link + "' is not in " + f.file);
    }
  } else {
    fu.model = single_link(f.name, "body", g);
  }
  forward_kinematics(fu.model, Eigen::VectorXd::Zero(0), f.pose, fu.link_poses);
  if (fu.srdf.path.empty()) fu.srdf.robot_name = f.name, fu.srdf.path = cell.file;
  if (!f.auto_supports) {
    fu.srdf.contacts = {contact_surface(f.name + "_supports", fu.model.links[0].name, f.supports)};
  } else if (fu.srdf.contacts.empty()) {
    for (size_t l = 0; l < fu.model.links.size(); ++l) {
      std::vector<Polygon3> polygons;
      for (const Geometry& geometry : fu.model.links[l].collisions) {
        const Triangles t = triangles_of(geometry);
        const auto found = support_surfaces(t.vertices, t.triangles, fu.link_poses[l], {.min_area = f.min_support_area});
        polygons.insert(polygons.end(), found.begin(), found.end());
      }
      if (!polygons.empty())
        fu.srdf.contacts.push_back(contact_surface(f.name + "_" + fu.model.links[l].name + "_top", fu.model.links[l].name, polygons));
    }
  }
  *supports = 0;
  for (const auto& c : fu.srdf.contacts) *supports += static_cast<int>(c.polygons.size());
  return fu;
}

SceneObject cell_part(const Cell& cell, size_t index, const ParallelGripper& gripper, const CellSceneOptions& o,
                      CellPartReport& report) {
  const CellPart& p = cell.parts[index];
  const std::string field = "parts[" + std::to_string(index) + "]";
  if (!fs::is_regular_file(p.mesh)) throw InputError(cell.file, field + ".mesh", "no such file: " + p.mesh);
  const auto mesh = mesh_of(p.mesh, o);
  report.part = p.name;
  SceneObject so;
  so.id = p.name;
  so.model_name = fs::path(p.mesh).stem().string();
  Geometry g;
  g.shape = MeshShape{p.mesh, Eigen::Vector3d::Constant(p.scale), mesh};
  g.color = p.color;
  so.model = single_link(p.name, "base_link", g);
  so.srdf.robot_name = p.name;
  so.srdf.path = cell.file;
  // Placements and handles from the mesh (the heavy part: Qhull, FCL hand checks), from the
  // cache when the same part was built before with the same gripper.
  auto derive = [&] {
    CellPartCache::Entry e;
    const Eigen::Vector3d com = centre_of_mass(*mesh, p.scale);
    if (p.auto_contacts) {
      std::vector<Eigen::Vector3d> points;
      for (const auto& v : mesh->vertices) points.push_back(v.cast<double>() * p.scale);
      try {
        for (const auto& r : resting_placements(points, com)) e.placements.push_back(r.polygon);
      } catch (const std::invalid_argument& ex) {
        throw InputError(p.mesh, "vertices", ex.what());
      }
    }
    if (p.auto_handles) {
      GraspOptions options;
      options.palm_clearance = cell.grasping.palm_clearance;
      options.max_handles = cell.grasping.max_handles;
      e.grasps = generate_handles(*mesh, p.scale, com, gripper, options, "base_link", p.name + "_grasp_");
    }
    return e;
  };
  std::ostringstream key;
  key.precision(17);
  key << p.mesh << '|' << p.scale << '|' << p.name << '|' << p.auto_contacts << p.auto_handles << '|'
      << cell.grasping.palm_clearance << '|' << cell.grasping.max_handles << '|' << gripper.opening << '|'
      << cell.robot.bundled << '|' << cell.robot.urdf << '|' << cell.robot.srdf;
  const CellPartCache::Entry derived = o.part_cache ? o.part_cache->get(key.str(), derive) : derive();
  if (p.auto_contacts) {
    if (derived.placements.empty()) throw InputError(cell.file, field + ".contacts", "the part has no face it can rest on");
    so.srdf.contacts = {contact_surface(p.name + "_surface", "base_link", derived.placements)};
    report.placements = static_cast<int>(derived.placements.size());
  } else {
    so.srdf.contacts = {contact_surface(p.name + "_surface", "base_link", p.contacts)};
    report.placements = static_cast<int>(p.contacts.size());
  }
  if (p.auto_handles) {
    report.grasps = derived.grasps;
    report.generated = true;
    if (report.grasps.handles.empty())
      throw InputError(cell.file, field + ".handles", "no grasp found for '" + p.name + "': " + report.grasps.why_none);
    for (const auto& h : report.grasps.handles) so.srdf.handles.push_back(h.frame);
  } else {
    if (p.handles.empty()) throw InputError(cell.file, field + ".handles", "the part has no handle");
    so.srdf.handles = p.handles;
  }
  return so;
}

}  // namespace

CellPartCache::Entry CellPartCache::get(const std::string& key, const std::function<Entry()>& make) {
  {
    std::lock_guard lock(mutex_);
    if (auto it = entries_.find(key); it != entries_.end()) return it->second;
  }
  Entry e = make();  // outside the lock: parts of one cell may be made in parallel
  std::lock_guard lock(mutex_);
  return entries_.emplace(key, std::move(e)).first->second;
}

Scene build_cell_scene(const Cell& cell, const CellSceneOptions& o, CellSceneReport* report) {
  CellSceneReport local;
  CellSceneReport& r = report ? *report : local;
  r = {};
  Scene scene;
  scene.name = cell.name.empty() ? fs::path(cell.file).stem().string() : cell.name;
  UrdfOptions urdf_options;
  urdf_options.package_paths = cell.package_paths;
  urdf_options.load_visual_meshes = o.load_visual_meshes;
  urdf_options.mesh_cache = o.mesh_cache;
  scene.robot = cell_robot(cell, o, urdf_options);
  for (size_t i = 0; i < cell.furniture.size(); ++i) {
    int supports = 0;
    scene.furniture.push_back(cell_furniture(cell, i, o, urdf_options, &supports));
    r.supports.push_back(supports);
  }
  // The parts on every core (each one's mesh, resting faces and grasps are its own); the first
  // part in order that fails raises its error, as reading them one by one would.
  const ParallelGripper gripper = parallel_gripper(scene.robot.model, scene.robot.srdf);
  std::vector<SceneObject> parts(cell.parts.size());
  std::vector<CellPartReport> reports(cell.parts.size());
  std::vector<std::exception_ptr> errors(cell.parts.size());
  parallel_for(cell.parts.size(), static_cast<int>(std::max(1u, std::thread::hardware_concurrency())), [&](size_t i) {
    try {
      parts[i] = cell_part(cell, i, gripper, o, reports[i]);
    } catch (...) {
      errors[i] = std::current_exception();
    }
  });
  for (size_t i = 0; i < cell.parts.size(); ++i) {
    if (errors[i]) std::rethrow_exception(errors[i]);
    scene.objects.push_back(std::move(parts[i]));
    r.parts.push_back(std::move(reports[i]));
  }
  return scene;
}

SceneState cell_start_state(const Cell& cell, const Scene& scene) {
  SceneState s;
  s.q = scene.robot.initial_configuration;
  for (const auto& p : cell.parts) s.objects.push_back(p.pose);
  return s;
}

}  // namespace demoplan
