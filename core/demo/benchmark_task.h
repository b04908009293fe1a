#pragma once
// A task of the guided-TAMP benchmark (gtamp/tasks/<task>_<demo>.json), as data.
// See resources/gtamp/README.md section 4 for every field.
#include <map>
#include <string>
#include <vector>

#include "core/scene/scene.h"

namespace demoplan {

struct BenchmarkObject {
  std::string id;  // YCBV_02, CUBOID_0.1_0.2_0.8, TRAY_0.3_0.3_0.3
  std::string urdf, srdf;  // absolute
  std::string model_name;
  bool in_planning_model = true;
};

struct BenchmarkFurniture {
  std::string kind;
  Pose pose;
  std::string urdf, srdf;  // absolute
};

struct BenchmarkTask {
  std::string data_dir;  // the gtamp folder
  std::string file;
  std::string task_name;  // shelf, tunnel, waiter, test
  int demo_id = 0;
  int frames = 0;  // T
  std::vector<BenchmarkObject> objects;
  std::vector<std::string> planning_object_ids;
  std::vector<PoseList> raw_poses;      // [object][frame], all objects incl. trays
  std::vector<PoseList> subgoal_poses;  // [planning object][column]; empty for test_0
  std::vector<std::vector<bool>> contacts;  // [object][frame]
  std::vector<BenchmarkFurniture> furniture;
  std::map<std::string, std::string> robot_pose_files;  // robot name -> absolute path

  std::string name() const { return task_name + "_" + std::to_string(demo_id); }
  // Rows of `objects` (and of raw_poses, contacts) that are planning objects, in the order of
  // planning_object_ids (object_ids without trays). Checked when the task is loaded.
  std::vector<size_t> planning_rows() const;
};

// Loads "<data_dir>/tasks/<name>.json" (name like "shelf_1"). Throws InputError.
BenchmarkTask load_benchmark_task(const std::string& data_dir, const std::string& name);

// Task names that have a file in <data_dir>/tasks, sorted.
std::vector<std::string> list_benchmark_tasks(const std::string& data_dir);

}  // namespace demoplan
