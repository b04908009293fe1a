#pragma once
// Exporting a planned path as a robot program from the GUI: the same pipeline as
// `demoplan-cli export` (time parameterization within the joint limits, the independent
// trajectory check, then the format's writer), returning what the dialog shows.
#include <string>
#include <vector>

#include "core/path/path.h"
#include "core/scene/scene.h"

namespace demoplan::ui {

struct ProgramFormat {
  std::string id;     // as core/export names it: urscript, krl, sunrise, franka, ros-yaml, csv
  std::string label;  // "Universal Robots (URScript)"
  std::string extension;  // ".script"
};
// Every format core/export writes, in its order.
std::vector<ProgramFormat> program_formats();

struct ProgramSettings {
  std::string format = "csv";
  double velocity_scale = 1.0;      // fraction of the joint velocity limits
  double acceleration_scale = 1.0;  // fraction of the acceleration (and jerk) limits
  double blend = 0.1;               // rad, joint-space blend at pass-through waypoints
  double rate = 0.0;                // Hz of sampled formats; 0: the format's default
  int gripper_output = -1;          // -1: the format's default
};

struct ProgramExport {
  bool ok = false;
  std::string error;  // why nothing was written
  double duration_s = 0.0;
  double trapezoid_duration_s = 0.0;
  double peak_velocity_ratio = 0.0, peak_acceleration_ratio = 0.0;
  bool check_ok = false;
  size_t blends = 0;       // corners passed without stopping, each checked collision-free
  size_t rests_added = 0;  // corners where a blend would touch the scene: the robot rests there
  std::vector<std::string> violations;
  std::vector<std::string> limits;  // one line per joint: the limits used
  std::vector<std::string> files;
  std::vector<std::string> warnings;
  std::string text;  // the files' content, concatenated (the preview)
};

// Writes the program to `file` (KRL: NAME.src and NAME.dat; Sunrise: CLASS.java). Never throws.
ProgramExport export_program_file(const Scene& scene, const Path& path, const std::string& data_dir,
                                  const ProgramSettings& settings, const std::string& file);

// A file name the format accepts, from a project name: "shelf_1.script", "SHELF_1.src",
// "Shelf1.java".
std::string program_file_name(const std::string& format, const std::string& stem);

}  // namespace demoplan::ui
