#pragma once
// Forward kinematics as free functions over a constant RobotModel.
#include <Eigen/Core>
#include <vector>

#include "core/geometry/se3.h"
#include "core/model/robot_model.h"

namespace demoplan {

// World pose of every link for configuration q, the root link placed at `base`.
// `link_poses` is resized to the number of links. Aligned allocation: Pose is fixed-size.
using PoseVector = std::vector<Pose, Eigen::aligned_allocator<Pose>>;
void forward_kinematics(const RobotModel& model, const Eigen::VectorXd& q, const Pose& base,
                        PoseVector& link_poses);

// Pose of one link; computes the chain from the root only.
Pose link_pose(const RobotModel& model, const Eigen::VectorXd& q, const Pose& base, int link);

// The transform a joint adds for its value: rotation about or translation along its axis.
Pose joint_motion(const Joint& joint, double value);

}  // namespace demoplan
