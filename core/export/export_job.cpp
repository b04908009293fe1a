#include "core/export/export_job.h"

#include <algorithm>

#include "core/error.h"
#include "core/export/program_writers.h"
#include "core/scene/collision_checker.h"
#include "core/trajectory/joint_limits.h"
#include "core/trajectory/time_parameterization.h"
#include "core/trajectory/trajectory_checker.h"
#include "core/validation/trajectory_collisions.h"

namespace demoplan {

ExportReport run_export_job(const Scene& scene, const Path& path, const ExportSettings& s) {
  const ProgramWriter& writer = program_writer(s.format, s.file);  // before the costly part
  const RobotModel& model = scene.robot.model;
  if (scene.robot.srdf.grippers.empty()) throw InputError(scene.robot.srdf.path, "gripper", "robot has no gripper");
  ExportOptions options;
  options.robot = scene.robot.name;
  options.source = s.source;
  options.rate = s.rate;
  options.close_output = s.gripper_output;
  options.open_output = s.gripper_open_output;
  options.servoj = s.servoj;
  options.krl_ptp = s.krl_ptp;

  LimitOverrides overrides;
  overrides.velocity_scale = s.velocity_scale;
  overrides.acceleration_scale = s.acceleration_scale;
  const JointLimitSet limits = trajectory_limits(model, overrides);
  TimingOptions timing;
  timing.source = s.source;
  timing.blend_length = s.blend;
  // The blends cut the path's corners: they are checked against the scene, and the robot rests
  // at the corners where they would touch something.
  const CollisionChecker checker(scene);
  const ClearTrajectory clear = time_parameterize_clear(scene, checker, path, limits, timing);
  const Trajectory& tr = clear.trajectory;

  ExportReport r;
  r.waypoints = path.waypoints.size();
  for (char stop : tr.stops) r.rests += stop;
  r.duration_s = tr.duration;
  r.trapezoid_duration_s = tr.trapezoid_duration;
  r.trapezoid_ratio = tr.trapezoid_duration / tr.duration;
  r.blends = tr.blends.size();
  r.rests_added = clear.rests_added.size();

  // The independent check, at the rate the controller gets samples at (one rule for every caller).
  r.rate_hz = writer.sample_rate(options);
  const auto samples = tr.sample(r.rate_hz, true);
  const CheckReport check = check_trajectory(samples, path, limits);
  r.samples_checked = samples.size();
  r.check_ok = check.ok;
  r.violations = check.violations;
  r.peak_velocity_ratio = check.peak_velocity_ratio;
  r.peak_acceleration_ratio = check.peak_acceleration_ratio;
  r.peak_jerk_ratio = check.peak_jerk_ratio;
  r.max_path_deviation = check.max_path_deviation;

  const RobotAxes axes = robot_axes(model, scene.robot.gripper().link, s.base_joints);
  std::vector<int> joints = axes.arm;
  joints.insert(joints.end(), axes.base.begin(), axes.base.end());
  r.limits = describe_limits(limits, joints);
  r.trajectory.joints = joints;
  r.trajectory.limits = limits;
  // ~2000 samples: enough for the plot's width, whatever the controller's rate.
  r.trajectory.samples = tr.sample(std::clamp(2000.0 / std::max(tr.duration, 1e-3), 20.0, 250.0), true);
  for (size_t i = 0; i < tr.stops.size() && i < tr.waypoint_times.size(); ++i)
    if (tr.stops[i]) {
      r.trajectory.rest_times.push_back(tr.waypoint_times[i]);
      r.trajectory.rest_actions.push_back(i < tr.actions.size() ? tr.actions[i] : GripperAction::None);
    }
  if (!check.ok) return r;

  ProgramOutput program = writer.write({path, tr, limits, model, axes, options}, s.file);
  r.files = std::move(program.files);
  r.warnings = std::move(program.warnings);
  r.streamed_samples = program.samples;
  return r;
}

}  // namespace demoplan
