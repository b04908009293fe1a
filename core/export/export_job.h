#pragma once
// The export pipeline, once for the CLI and the GUI: time the path within the robot's limits
// (resting where a blend would touch the scene), check the timed trajectory independently at the
// rate the format streams at, and write the program in memory. Nothing is written to disk:
// the caller does that with write_program_files() when the user exports.
#include <string>
#include <vector>

#include "core/export/program_file.h"
#include "core/path/path.h"
#include "core/scene/scene.h"
#include "core/trajectory/joint_limits.h"
#include "core/trajectory/trajectory.h"

namespace demoplan {

struct ExportSettings {
  std::string format = "csv";       // a program_writers() id
  double velocity_scale = 1.0;      // fraction of the joint velocity limits
  double acceleration_scale = 1.0;  // fraction of the acceleration (and jerk) limits
  double blend = 0.1;               // rad, joint-space blend at pass-through waypoints
  double rate = 0.0;                // Hz of sampled output; 0: the format's default
  int gripper_output = -1;          // digital output closing the gripper; -1: the format's default
  int gripper_open_output = -1;     // one opening it, for two-output grippers; -1: none
  bool servoj = false;              // URScript: a servoj stream instead of movej waypoints
  bool krl_ptp = false;             // KRL: PTP with C_PTP instead of PTP_SPLINE blocks
  std::vector<std::string> base_joints;  // the mobile base's joint names (benchmark_base_joints)
  std::string source = "path";      // the path's file: named in errors about the path and in the header
  std::string file;                 // the program's file: names the module or class; named in errors
};

// The timed trajectory for display (the export dialog's joint plots): sampled densely enough
// to show the jerk-limited profile's phases, yet a few thousand samples at most.
struct ExportTrajectory {
  std::vector<int> joints;                // exported configuration slots: the arm, then the base
  std::vector<TrajectorySample> samples;  // every waypoint's time is a sample
  JointLimitSet limits;                   // per configuration slot, scaled as the export used them
  std::vector<double> rest_times;         // s: where the robot stands still (ends, grasps, releases)
  std::vector<GripperAction> rest_actions;  // per rest, what the gripper does there
};

struct ExportReport {
  size_t waypoints = 0;
  size_t rests = 0;  // waypoints where the robot stands still (ends, grasps, releases, clearance)
  double duration_s = 0.0;
  double trapezoid_duration_s = 0.0;  // resting at every waypoint instead
  double trapezoid_ratio = 0.0;       // trapezoid_duration_s / duration_s
  double rate_hz = 0.0;               // the format's sample rate, at which the check ran
  size_t samples_checked = 0;
  double peak_velocity_ratio = 0.0, peak_acceleration_ratio = 0.0, peak_jerk_ratio = 0.0;
  double max_path_deviation = 0.0;
  bool check_ok = false;
  std::vector<std::string> violations;
  size_t blends = 0;       // corners passed without stopping, each checked collision-free
  size_t rests_added = 0;  // corners where a blend would touch the scene: the robot rests there
  std::vector<std::string> limits;  // one line per joint group: the limits used
  ExportTrajectory trajectory;      // also when the check failed: the plots show where
  // From the writer, only when the check passed: the program's files, remarks, streamed samples.
  std::vector<ProgramFile> files;
  std::vector<std::string> warnings;
  size_t streamed_samples = 0;
};

// Throws InputError for bad input: an unknown format or one that does not fit the robot (naming
// settings.file), a waypoint beyond a joint limit (naming settings.source), a robot without
// limits (naming its URDF). A trajectory that fails the check is not bad input: check_ok is
// false and there are no files.
ExportReport run_export_job(const Scene& scene, const Path& path, const ExportSettings& settings);

}  // namespace demoplan
