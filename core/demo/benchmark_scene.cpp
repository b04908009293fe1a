#include "core/demo/benchmark_scene.h"

#include <filesystem>

#include "core/error.h"
#include "core/geometry/polygon_2d.h"
#include "core/io/json_file.h"
#include "core/model/concurrent_urdfs.h"

namespace demoplan {

namespace fs = std::filesystem;

namespace {

JsonField robot_entry(const Json& json, const std::string& file, const std::string& name) {
  const JsonField robots = JsonField(json, file)["robots"];
  if (!robots.has(name)) {
    std::string known;
    for (const auto& [k, _] : robots.value().items()) known += (known.empty() ? "" : ", ") + k;
    robots.fail("no robot '" + name + "' (known: " + known + ")");
  }
  return robots[name];
}

// The box the benchmark puts under a fixed robot, from the pose file (README 5.1). The file
// keeps the benchmark's negative heights where the base is below a shelf top; the box then
// spans |height| (it only matters for objects and moving links). A zero-size box is omitted.
bool add_support_box(const Pose& pose, const Eigen::Vector3d& raw_size, const std::string& name, Scene& scene) {
  const Eigen::Vector3d size = raw_size.cwiseAbs();
  if ((size.array() <= 0).any()) return false;
  SceneFurniture box;
  box.name = name;
  box.kind = kSupportBoxKind;
  box.model.name = name;
  box.model.links.push_back({});
  box.model.links[0].name = "box";
  box.model.links[0].collisions.push_back({BoxShape{size}, Pose::Identity(), {0.43, 0.34, 0.24, 0.9}});
  box.model.links[0].visuals = box.model.links[0].collisions;
  box.link_poses = {pose};
  scene.furniture.push_back(std::move(box));
  return true;
}


// Every handle and contact surface of an SRDF must sit on a link of its URDF.
void check_srdf_links(const Srdf& srdf, const RobotModel& model, const std::string& urdf) {
  for (const auto& h : srdf.handles)
    if (model.link_index(h.link) < 0)
      throw InputError(srdf.path, "handle '" + h.name + "' link", "link '" + h.link + "' is not in " + urdf);
  for (const auto& c : srdf.contacts)
    if (model.link_index(c.link) < 0)
      throw InputError(srdf.path, "contact '" + c.name + "' link", "link '" + c.link + "' is not in " + urdf);
}
}  // namespace

BenchmarkRobot load_benchmark_robot(const std::string& data_dir, const std::string& name) {
  const std::string file = (fs::path(data_dir) / "robots" / "robots.json").string();
  const Json json = read_json_file(file);
  const JsonField r = robot_entry(json, file, name);
  BenchmarkRobot out;
  out.name = name;
  out.urdf = (fs::path(data_dir) / r["urdf"].string()).lexically_normal().string();
  out.srdf = (fs::path(data_dir) / r["srdf"].string()).lexically_normal().string();
  const std::string type = r["robot_type"].string();
  if (type != "fixed" && type != "mobile") r["robot_type"].fail("must be 'fixed' or 'mobile'");
  out.fixed_base = type == "fixed";
  out.initial_configuration = r["initial_configuration"].vector();
  if (r.has("footprint_size")) {
    const Eigen::VectorXd size = r["footprint_size"].vector(), offset = r["footprint_pos"].vector();
    if (size.size() != 2) r["footprint_size"].fail("must have 2 entries");
    if (offset.size() != 2) r["footprint_pos"].fail("must have 2 entries");
    out.footprint_size = size, out.footprint_offset = offset;
  }
  return out;
}

std::vector<std::string> list_benchmark_robots(const std::string& data_dir) {
  const std::string file = (fs::path(data_dir) / "robots" / "robots.json").string();
  const Json json = read_json_file(file);
  std::vector<std::string> out;
  for (const auto& [k, _] : JsonField(json, file)["robots"].value().items()) out.push_back(k);
  return out;
}

std::vector<int> benchmark_pose_ids(const BenchmarkTask& task, const std::string& robot) {
  auto it = task.robot_pose_files.find(robot);
  if (it == task.robot_pose_files.end()) return {};
  const Json json = read_json_file(it->second);
  const JsonField ids = JsonField(json, it->second)["pose_ids"];
  std::vector<int> out;
  for (size_t i = 0; i < ids.size(); ++i) out.push_back(ids[i].integer());
  return out;
}

namespace {
// The task's pose file for the robot, read, and the key of `pose_id` in it (checked).
std::pair<Json, std::string> pose_file_entry(const BenchmarkTask& task, const std::string& robot_name, int pose_id) {
  auto pose_file = task.robot_pose_files.find(robot_name);
  if (pose_file == task.robot_pose_files.end()) {
    std::string known;
    for (const auto& [k, _] : task.robot_pose_files) known += (known.empty() ? "" : ", ") + k;
    throw InputError(task.file, "robot_poses", "task has no poses for robot '" + robot_name +
                                                   "' (it has: " + known + ")");
  }
  Json json = read_json_file(pose_file->second);
  const JsonField poses(json, pose_file->second);
  const std::string key = std::to_string(pose_id);
  if (!poses["poses"].has(key)) {
    std::string known;
    for (const auto& [k, _] : poses["poses"].value().items()) known += (known.empty() ? "" : ", ") + k;
    poses["poses"].fail("no robot pose id " + key + " (available: " + known + ")");
  }
  return {std::move(json), key};
}
}  // namespace

Pose benchmark_robot_pose(const BenchmarkTask& task, const std::string& robot, int pose_id) {
  const auto [json, key] = pose_file_entry(task, robot, pose_id);
  return JsonField(json, task.robot_pose_files.at(robot))["poses"][key].pose();
}

Scene build_benchmark_scene(const BenchmarkTask& task, const std::string& robot_name, int pose_id,
                            const SceneLoadOptions& options) {
  Scene scene;
  scene.name = task.name() + " " + robot_name + " pose " + std::to_string(pose_id);
  UrdfOptions urdf_options;
  urdf_options.load_visual_meshes = options.load_visual_meshes;
  urdf_options.mesh_cache = options.mesh_cache;

  // Robot.
  const BenchmarkRobot info = load_benchmark_robot(task.data_dir, robot_name);
  const auto [poses_json, key] = pose_file_entry(task, robot_name, pose_id);
  const JsonField poses(poses_json, task.robot_pose_files.at(robot_name));
  // Every URDF read at once: the robot's, then the furniture's, then the planning objects'.
  std::vector<std::string> urdfs = {info.urdf};
  for (const auto& f : task.furniture) urdfs.push_back(f.urdf);
  const std::vector<size_t> rows = task.planning_rows();
  for (size_t row : rows) urdfs.push_back(task.objects[row].urdf);
  ConcurrentUrdfs models(urdfs, urdf_options);
  size_t next_model = 0;
  SceneRobot& robot = scene.robot;
  robot.name = robot_name;
  robot.model = models.take(next_model++);
  robot.srdf = load_srdf(info.srdf);
  robot.base = poses["poses"][key].pose();
  robot.fixed_base = info.fixed_base;
  robot.initial_configuration = info.initial_configuration;
  if (robot.initial_configuration.size() != robot.model.nq)
    throw InputError((fs::path(task.data_dir) / "robots" / "robots.json").string(),
                     "robots." + robot_name + ".initial_configuration",
                     "has " + std::to_string(robot.initial_configuration.size()) + " entries, " + info.urdf +
                         " has " + std::to_string(robot.model.nq) + " joints");
  if (robot.srdf.grippers.empty()) throw InputError(info.srdf, "gripper", "robot has no gripper");
  robot.gripper_link = robot.model.link_index(robot.gripper().link);
  if (robot.gripper_link < 0)
    throw InputError(info.srdf, "gripper '" + robot.gripper().name + "' link",
                     "link '" + robot.gripper().link + "' is not in " + info.urdf);

  // Furniture, then the support box (the benchmark appends it last).
  for (size_t i = 0; i < task.furniture.size(); ++i) {
    const auto& f = task.furniture[i];
    SceneFurniture fu;
    fu.kind = f.kind;
    fu.name = fs::path(f.urdf).stem().string();
    fu.model = models.take(next_model++);
    fu.srdf = load_srdf(f.srdf);
    check_srdf_links(fu.srdf, fu.model, f.urdf);
    forward_kinematics(fu.model, Eigen::VectorXd::Zero(fu.model.nq), Pose::Identity(), fu.link_poses);
    if (fu.model.nq != 0) throw InputError(f.urdf, "", "furniture must have only fixed joints");
    if (task.task_name == "tunnel" && f.kind == "tunnel")
      fu.robot_ignored_links = {"left_sideB", "right_sideB", "top_sideB"};
    scene.furniture.push_back(std::move(fu));
  }
  if (robot.fixed_base) {
    const JsonField box = poses["support_box"][key];
    const Eigen::VectorXd size = box["size"].vector();
    if (size.size() != 3) box["size"].fail("must have 3 entries");
    add_support_box(box["pose"].pose(), size, task.name() + "_" + std::to_string(task.furniture.size()) + "_box_" +
                                    robot_name + "_" + key, scene);
  }

  // Planning objects (trays are not part of the collision model), in planning_object_ids order.
  for (size_t row : rows) {
    const auto& o = task.objects[row];
    SceneObject so;
    so.id = o.id;
    so.model_name = o.model_name;
    so.model = models.take(next_model++);
    so.srdf = load_srdf(o.srdf);
    check_srdf_links(so.srdf, so.model, o.urdf);
    if (so.model.nq != 0) throw InputError(o.urdf, "", "objects must be rigid (fixed joints only)");
    scene.objects.push_back(std::move(so));
  }
  return scene;
}

SupportBox support_box_at(const Scene& scene, const BenchmarkRobot& robot, const Pose& base) {
  const Eigen::Vector3d p = base.translation();
  double h = 0;
  for (auto f = scene.furniture.rbegin(); f != scene.furniture.rend(); ++f) {
    if (f->kind == kSupportBoxKind) continue;
    for (const ContactSurface& c : f->srdf.contacts) {
      const Pose& link = f->link_poses[static_cast<size_t>(f->model.link_index(c.link))];
      for (auto polygon : c.polygon_vertices()) {
        for (Eigen::Vector3d& v : polygon) v = link * v;
        const double zs = polygon.front().z();
        // (The benchmark's polygons are counter-clockwise.)
        if (contains_from_above(polygon, p) && zs > h) h = p.z() - zs;  // a height against a height difference, as written
      }
    }
  }
  SupportBox box;
  const double height = h == 0 ? p.z() : h;
  box.size = {robot.footprint_size.x(), robot.footprint_size.y(), height};
  Pose centre = base;
  centre.translation() = Eigen::Vector3d(p.x(), p.y(), p.z() - height / 2);
  box.pose = centre * Pose(Eigen::Translation3d(robot.footprint_offset.x(), robot.footprint_offset.y(), 0));
  return box;
}

void move_benchmark_robot(Scene& scene, const BenchmarkRobot& robot, const Pose& base) {
  if (!robot.fixed_base)
    throw InputError(robot.urdf, "robot_type",
                     robot.name + " is mobile: its base moves through its own joints, it is not stood anywhere");
  std::string name;
  for (auto f = scene.furniture.begin(); f != scene.furniture.end();)
    if (f->kind == kSupportBoxKind) name = f->name, f = scene.furniture.erase(f);
    else ++f;
  scene.robot.base = base;
  const SupportBox box = support_box_at(scene, robot, base);
  add_support_box(box.pose, box.size, name.empty() ? "support_box_" + robot.name : name, scene);
}

namespace {
SceneState state_at(const BenchmarkTask& task, const Scene& scene, bool goal) {
  SceneState s;
  s.q = scene.robot.initial_configuration;
  const std::vector<size_t> rows = task.planning_rows();
  for (size_t i = 0; i < rows.size(); ++i) {
    const PoseList& track = task.subgoal_poses.empty() ? task.raw_poses[rows[i]] : task.subgoal_poses[i];
    s.objects.push_back(goal ? track.back() : track.front());
  }
  return s;
}
}  // namespace

SceneState benchmark_start_state(const BenchmarkTask& task, const Scene& scene) {
  return state_at(task, scene, false);
}

SceneState benchmark_goal_state(const BenchmarkTask& task, const Scene& scene) {
  return state_at(task, scene, true);
}

}  // namespace demoplan
