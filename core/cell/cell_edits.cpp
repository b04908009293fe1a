#include "core/cell/cell_edits.h"

#include <algorithm>
#include <filesystem>
#include <random>

#include "core/demo/benchmark_scene.h"
#include "core/error.h"
#include "core/placement/base_clearance.h"
#include "core/model/mesh.h"
#include "core/model/mobile_base.h"
#include "core/model/package_paths.h"
#include "core/scene/collision_checker.h"
#include "core/scene/resting_pose_sampler.h"

namespace demoplan {

namespace {

bool name_taken(const Cell& cell, const std::string& name) {
  for (const auto& f : cell.furniture)
    if (f.name == name) return true;
  return cell.part_index(name) >= 0;
}

constexpr double kPedestalHeight = 0.75;

// A box of `height` under the robot's base that nothing is put down on, the base on its top.
CellFurniture pedestal_under(const Cell& cell, const Pose& base, double height) {
  CellFurniture pedestal;
  pedestal.name = unique_cell_name(cell, "pedestal");
  pedestal.box = {0.3, 0.3, height};
  pedestal.pose.linear() = base.linear();
  pedestal.pose.translation() = Eigen::Vector3d(base.translation().x(), base.translation().y(), height / 2);
  pedestal.auto_supports = false;  // nothing is put down on the robot's pedestal
  return pedestal;
}

}  // namespace

std::string unique_cell_name(const Cell& cell, const std::string& base) {
  if (!name_taken(cell, base)) return base;
  for (int k = 2;; ++k)
    if (const std::string n = base + " " + std::to_string(k); !name_taken(cell, n)) return n;
}

Cell starter_cell(const std::string& file, const std::string& robot, const std::string& data_dir) {
  const BenchmarkRobot r = load_benchmark_robot(data_dir, robot);  // throws for an unknown robot
  Cell c;
  c.file = std::filesystem::absolute(file).lexically_normal().string();
  c.name = std::filesystem::path(file).stem().string();
  c.robot.bundled = robot;
  c.robot.mobile = !r.fixed_base;
  const double top = kPedestalHeight;
  if (r.fixed_base) {
    c.robot.base.translation() = Eigen::Vector3d(0, 0, top);
    c.furniture.push_back(pedestal_under(c, c.robot.base, top));
  }
  CellFurniture table;
  table.name = "table";
  table.box = {0.8, 1.2, top};
  table.pose.translation() = Eigen::Vector3d(r.fixed_base ? 0.65 : 1.2, 0, top / 2);
  c.furniture.push_back(table);
  return c;
}

void replace_robot(Cell& cell, const std::string& bundled, const std::string& urdf, const std::string& srdf,
                   const std::string& data_dir) {
  CellRobot robot;
  robot.base = cell.robot.base;
  if (!bundled.empty()) {
    const BenchmarkRobot r = load_benchmark_robot(data_dir, bundled);  // throws for an unknown robot
    robot.bundled = bundled;
    robot.mobile = !r.fixed_base;
  } else {
    for (const auto& [path, what] : {std::pair{urdf, "robot URDF"}, std::pair{srdf, "robot SRDF"}})
      if (!std::filesystem::is_regular_file(path)) throw InputError(path, "", std::string(what) + ": no such file");
    robot.urdf = std::filesystem::absolute(urdf).lexically_normal().string();
    robot.srdf = std::filesystem::absolute(srdf).lexically_normal().string();
    for (const std::string& dir : guess_package_paths(robot.urdf))
      if (std::find(cell.package_paths.begin(), cell.package_paths.end(), dir) == cell.package_paths.end())
        cell.package_paths.push_back(dir);
  }
  if (robot.mobile) robot.base.translation().z() = 0.0;  // a mobile base drives on the floor
  cell.robot = robot;
}

void set_robot_mobile(Cell& cell, const Scene& scene, bool mobile) {
  if (!cell.robot.bundled.empty())
    throw InputError(cell.file, "robot.mobile",
                     "the bundled " + cell.robot.bundled + " is " + (cell.robot.mobile ? "mobile" : "fixed") +
                         " as its data says; a robot from URDF and SRDF files can be made mobile");
  if (mobile == cell.robot.mobile) return;
  Pose& base = cell.robot.base;
  const int pedestal = robot_pedestal(scene);  // scene furniture i is the cell's furniture i
  if (mobile) {
    if (const std::string problem = mobile_base_problem(scene.robot.model, std::filesystem::path(cell.robot.urdf).filename().string());
        !problem.empty())
      throw InputError(cell.file, "robot.mobile", problem);
    if (pedestal >= 0) cell.furniture.erase(cell.furniture.begin() + pedestal);  // it drives off it
    base.translation().z() = 0.0;  // a mobile base drives on the floor
  } else if (pedestal < 0 && furniture_under_base(scene) < 0) {
    // Standing on the floor: an arm needs something to stand on at a working height.
    const double height = base.translation().z() > 0.05 ? base.translation().z() : kPedestalHeight;
    base.translation().z() = height;
    cell.furniture.push_back(pedestal_under(cell, base, height));
  }
  cell.robot.mobile = mobile;
}

double guess_unit_scale(const std::string& mesh_file) {
  const auto mesh = load_mesh(mesh_file);
  return mesh->bounds().sizes().maxCoeff() > 3.0f ? 0.001 : 1.0;
}

int add_part_from_mesh(Cell& cell, const std::string& mesh_file, double scale, const CellSceneOptions& options) {
  if (!(scale > 0)) throw InputError(mesh_file, "scale", "must be > 0");
  load_mesh(mesh_file);  // a missing or empty file is named as such, before anything else
  Cell with = cell;
  CellPart part;
  part.name = unique_cell_name(cell, std::filesystem::path(mesh_file).stem().string());
  part.mesh = std::filesystem::absolute(mesh_file).lexically_normal().string();
  part.scale = scale;
  part.pose.translation() = Eigen::Vector3d(0, 0, -100);  // out of the way until put down
  with.parts.push_back(part);
  const int index = static_cast<int>(with.parts.size()) - 1;
  Scene scene;
  try {
    scene = build_cell_scene(with, options);
  } catch (const InputError& e) {
    // The cell file is not the user's concern here: the part's mesh is.
    throw InputError(mesh_file, e.field().rfind("parts[", 0) == 0 ? e.field().substr(e.field().find('.') + 1) : e.field(),
                     e.reason());
  }
  const RestingPoseSampler sampler(scene);
  if (sampler.empty()) throw InputError(mesh_file, "", "the cell has no support to put the part down on: add a table");
  const CollisionChecker checker(scene);
  CollisionData data = checker.make_data();
  SceneState state = cell_start_state(with, scene);
  std::mt19937_64 rng(1);
  for (int draw = 0; draw < 300; ++draw) {
    const std::optional<Pose> at = sampler.sample(index, rng);
    if (!at) continue;
    state.objects[static_cast<size_t>(index)] = *at;
    if (checker.in_collision(state, data)) continue;
    with.parts.back().pose = *at;
    cell = std::move(with);
    return index;
  }
  throw InputError(mesh_file, "", "no support has a free spot for the part: make room or add a table");
}

Demonstration demonstration_for_parts(const Demonstration& demo, const Scene& scene, const SceneState& start) {
  Demonstration d = demo;
  d.object_ids.clear();
  for (const auto& o : scene.objects) d.object_ids.push_back(o.id);
  std::vector<int> old_of(d.object_ids.size(), -1);  // new object index -> old one, -1 new part
  for (size_t k = 0; k < d.object_ids.size(); ++k) old_of[k] = demo.object_index(d.object_ids[k]);
  for (size_t old = 0; old < demo.object_ids.size(); ++old)
    if (std::find(old_of.begin(), old_of.end(), static_cast<int>(old)) == old_of.end())
      for (const auto& e : demo.events)
        if (e.object == static_cast<int>(old))
          throw InputError(demo.object_ids[old], "events",
                           "the demonstration grasps or releases it (frame " + std::to_string(e.frame) +
                               "): delete its events first");
  for (size_t i = 0; i < d.events.size(); ++i) {
    const ContactEvent& before = demo.events[i];
    ContactEvent& e = d.events[i];
    e.object = static_cast<int>(std::find(old_of.begin(), old_of.end(), before.object) - old_of.begin());
    e.poses.clear();
    e.pose_frames.clear();
    for (size_t k = 0; k < old_of.size(); ++k) {
      const bool kept = old_of[k] >= 0 && static_cast<size_t>(old_of[k]) < before.poses.size();
      e.poses.push_back(kept ? before.poses[static_cast<size_t>(old_of[k])] : start.objects[k]);
      if (!before.pose_frames.empty()) e.pose_frames.push_back(kept ? before.pose_frame(old_of[k]) : "");
    }
  }
  std::erase_if(d.doubts, [&](const DetectionDoubt& x) {
    return std::find(old_of.begin(), old_of.end(), x.object) == old_of.end();
  });
  for (auto& x : d.doubts) x.object = static_cast<int>(std::find(old_of.begin(), old_of.end(), x.object) - old_of.begin());
  return d;
}

}  // namespace demoplan
