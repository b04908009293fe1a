#pragma once
// ROS: trajectory_msgs/JointTrajectory messages as YAML (ROS 2 field names), one per motion
// between two rests, with the URDF's joint names (arm and base; the fingers are the gripper's
// business). After each, `gripper_after` says whether to grasp or release before the next one.
// Points every 1/rate s plus one exactly at each waypoint.
#include "core/export/program_writer.h"

namespace demoplan {

const ProgramWriter& ros_yaml_writer();

}  // namespace demoplan
