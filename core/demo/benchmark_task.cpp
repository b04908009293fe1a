#include "core/demo/benchmark_task.h"

#include <algorithm>
#include <filesystem>
#include <regex>

#include "core/error.h"
#include "core/io/json_file.h"

namespace demoplan {

namespace fs = std::filesystem;

namespace {

std::string data_path(const std::string& data_dir, const JsonField& f) {
  const fs::path p = fs::path(data_dir) / f.string();
  std::error_code ec;
  if (!fs::exists(p, ec)) f.fail("file not found: " + p.string());
  return p.lexically_normal().string();
}

std::vector<PoseList> pose_grid(const JsonField& f, size_t rows, size_t cols) {
  if (f.size() != rows) f.fail("expected " + std::to_string(rows) + " rows, found " + std::to_string(f.size()));
  std::vector<PoseList> out(rows);
  for (size_t i = 0; i < rows; ++i) {
    const JsonField row = f[i];
    if (row.size() != cols)
      row.fail("expected " + std::to_string(cols) + " poses, found " + std::to_string(row.size()));
    for (size_t t = 0; t < cols; ++t) out[i].push_back(row[t].pose());
  }
  return out;
}

}  // namespace

BenchmarkTask load_benchmark_task(const std::string& data_dir, const std::string& name) {
  BenchmarkTask task;
  task.data_dir = data_dir;
  task.file = (fs::path(data_dir) / "tasks" / (name + ".json")).string();
  std::error_code ec;
  if (!fs::exists(task.file, ec)) {
    std::string known;
    for (const auto& t : list_benchmark_tasks(data_dir)) known += (known.empty() ? "" : ", ") + t;
    throw InputError(task.file, "", "no such task '" + name + "' (known: " + known + ")");
  }
  const Json json = read_json_file(task.file);
  const JsonField root(json, task.file);
  if (root["format"].string() != "gtamp-task-v1") root["format"].fail("expected gtamp-task-v1");
  task.task_name = root["task_name"].string();
  task.demo_id = root["demo_id"].integer();
  task.frames = root["T"].integer();
  const int n = root["n_objects"].integer();
  if (task.frames < 1) root["T"].fail("must be >= 1");

  const JsonField objects = root["objects"];
  if (objects.size() != static_cast<size_t>(n)) objects.fail("must have n_objects entries");
  for (size_t i = 0; i < objects.size(); ++i) {
    const JsonField o = objects[i];
    task.objects.push_back({o["id"].string(), data_path(data_dir, o["urdf"]),
                            data_path(data_dir, o["srdf"]), o["model_name"].string(),
                            o["in_planning_model"].boolean()});
  }
  const JsonField planning = root["planning_object_ids"];
  for (size_t i = 0; i < planning.size(); ++i) {
    const std::string id = planning[i].string();
    if (std::none_of(task.objects.begin(), task.objects.end(), [&](auto& o) { return o.id == id; }))
      planning[i].fail("'" + id + "' is not in objects");
    task.planning_object_ids.push_back(id);
  }

  const std::vector<size_t> rows = task.planning_rows();
  if (rows.size() != task.planning_object_ids.size())
    planning.fail("must list the objects with in_planning_model, in order");
  for (size_t i = 0; i < rows.size(); ++i)
    if (task.objects[rows[i]].id != task.planning_object_ids[i])
      planning[i].fail("must equal object_ids without trays, in order");

  task.raw_poses = pose_grid(root["objects_poses"], n, task.frames);
  const JsonField subgoals = root["subgoal_objects_poses"];
  if (!subgoals.is_null()) {
    const int s = root["n_subgoals"].integer();
    if (s < 2) root["n_subgoals"].fail("must be >= 2 (start and goal)");
    task.subgoal_poses = pose_grid(subgoals, task.planning_object_ids.size(), s);
  }

  const JsonField contacts = root["contacts"];
  if (contacts.size() != static_cast<size_t>(n)) contacts.fail("must have n_objects rows");
  for (size_t i = 0; i < contacts.size(); ++i) {
    const JsonField row = contacts[i];
    if (row.size() != static_cast<size_t>(task.frames)) row.fail("must have T entries");
    auto& out = task.contacts.emplace_back();
    for (size_t t = 0; t < row.size(); ++t) out.push_back(row[t].boolean());
  }

  const JsonField ids = root["furniture_ids"], poses = root["furniture_poses"],
                  urdfs = root["furniture_urdf"], srdfs = root["furniture_srdf"];
  for (size_t i = 0; i < ids.size(); ++i)
    task.furniture.push_back({ids[i].string(), poses[i].pose(), data_path(data_dir, urdfs[i]),
                              data_path(data_dir, srdfs[i])});

  const JsonField robot_poses = root["robot_poses"];
  for (const auto& [robot, _] : robot_poses.value().items())
    task.robot_pose_files[robot] = data_path(data_dir, robot_poses[robot]);
  return task;
}

std::vector<size_t> BenchmarkTask::planning_rows() const {
  std::vector<size_t> rows;
  for (size_t i = 0; i < objects.size(); ++i)
    if (objects[i].in_planning_model) rows.push_back(i);
  return rows;
}

std::vector<std::string> list_benchmark_tasks(const std::string& data_dir) {
  std::vector<std::string> out;
  const std::regex task_file(R"(([a-z]+_[0-9]+)\.json)");
  std::error_code ec;
  for (const auto& e : fs::directory_iterator(fs::path(data_dir) / "tasks", ec)) {
    std::smatch m;
    const std::string f = e.path().filename().string();
    if (std::regex_match(f, m, task_file)) out.push_back(m[1]);
  }
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace demoplan
