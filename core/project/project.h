#pragma once
// The project file: everything the operator works on, in one versioned JSON file.
//
// {"format": "demoplan-project", "version": 1,
//  "scene": {"task": "shelf_1", "robot": "panda", "pose": 1,
//            "data_dir": "..."},               // optional; absent: the bundled benchmark data
//      or  {"cell": "my.cell.json"},           // a cell the user built (docs/cell.md)
//  "video": "video.mp4",                       // relative to the project file; "" when none
//  "camera": "camera.json",                    // demoplan-camera or OpenCV calibration; "" none
//  "markers": "markers.json",                  // demoplan-marker-scene: which markers are on which
//                                              // part (to detect the events in the video); "" none
//  "demonstration": {"format": "demoplan-demonstration", "version": 1, ...},  // with the edits
//  "planner": {...},                           // core/planning/planner_settings.h
//  "result": {"path": "x.path.json", ...summary of the last run} | null,
//  "tracker_corrections": [{"id": "YCBV_03", "frame": 92, "world_T_object": 4x4 row-major}],
//                                              // optional: parts the operator placed again for
//                                              // the part-model tracker (part_correction.h)
//  "view": {"frame": 0}}
// Paths are stored relative to the project file's folder (absolute paths are kept as they are)
// and held absolute in memory. Units: metres, radians, seconds.
#include <optional>
#include <string>

#include "core/demo/demonstration.h"
#include "core/demo/part_correction.h"
#include "core/io/json_file.h"
#include "core/placement/placement_region.h"
#include "core/planning/plan_job.h"
#include "core/planning/planner_settings.h"

namespace demoplan {

inline constexpr const char* kProjectFormat = "demoplan-project";
inline constexpr int kProjectVersion = 1;
inline constexpr const char* kProjectExtension = "demoplan";

struct SceneReference {
  std::string data_dir;  // absolute; empty: the bundled benchmark data
  std::string task = "shelf_1";
  std::string robot = "panda";
  int pose = 0;
  std::string cell;  // absolute; when set, the scene is this cell file (docs/cell.md), not a task
  // A task's robot stood where the operator chose (the placement search) instead of at `pose`:
  // its support box is made for it (benchmark README 5.1). A cell keeps its base in the cell.
  std::optional<BasePose> base;
  bool is_cell() const { return !cell.empty(); }
  std::string describe() const;  // "shelf_1, panda pose 0" or the cell file's name
  bool operator==(const SceneReference&) const = default;
};

// What the last planning run produced, as the result panel shows it. The path itself lives in
// its own "demoplan-path" file beside the project.
struct ResultSummary {
  std::string path;  // absolute path of the path file
  bool solved = false;
  bool valid = false;
  std::string message;     // the validator's message, or why planning failed
  std::string validated_against;
  double planning_time_s = 0.0;
  long iterations = 0;
  int trees = 0;
  size_t nodes = 0;
  double length_robot_rad = 0.0;
  double length_object_m = 0.0;
  double length_object_rad = 0.0;
  int grasps = 0;          // as the benchmark counts them (path_validator.h)
  int gripper_closes = 0;  // the path's own grasp actions
  bool shortened = false;
  std::string demonstration_digest;  // of the demonstration it was planned for
};

// The summary of a plan job's report, as the project file stores it (the path file and the
// demonstration digest are the caller's).
ResultSummary summarize(const PlanReport& report, const std::string& validated_against);

struct Project {
  SceneReference scene;
  std::string video;   // absolute; empty when none
  std::string camera;  // absolute; empty when none
  std::string markers;  // absolute; empty when none
  Demonstration demonstration;
  PlannerSettings planner;
  std::optional<ResultSummary> result;
  // Where the operator placed parts again for the part-model tracker, in the order placed: one
  // per part and frame, each frame after 0, each id one of the demonstration's.
  std::vector<PartCorrection> tracker_corrections;
  int frame = 0;  // where the playhead was
};

// Reads and writes the project file. Saving is atomic. Loading throws InputError naming the
// file and the field; a file of another format or version is rejected with a clear message.
void save_project(const std::string& file, const Project& project);
Project load_project(const std::string& file);

Json project_to_json(const Project& project, const std::string& file);
Project project_from_json(const Json& json, const std::string& file);

// A short stable digest of a demonstration (FNV-1a of its JSON), to tell whether a result is
// out of date.
std::string demonstration_digest(const Demonstration& demo);

}  // namespace demoplan
