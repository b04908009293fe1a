#pragma once
// A mobile base read from the kinematic tree: the root is followed by massless links joined by
// two prismatic joints along independent horizontal axes and then a revolute joint about the
// vertical (x, y, yaw, as the KMR's URDF writes its platform), ending at the first link with
// collision geometry, the base body. A fixed-base arm has no such chain.
#include <Eigen/Core>
#include <optional>
#include <string>

#include "core/geometry/se3.h"
#include "core/model/robot_model.h"

namespace demoplan {

struct MobileBase {
  int x = -1, y = -1, yaw = -1;  // configuration slots of the planar joints, in chain order
  int body = -1;                 // link index of the base body
  double yaw_sign = 1.0;         // +1 when the yaw joint turns about +z of the root

  // World pose of the base body at q (only the planar slots of q are read), the root at `root`.
  Pose body_pose(const RobotModel& model, const Eigen::VectorXd& q, const Pose& root) const;
  // Writes the planar slots of q so the body sits at world (x, y) with world yaw `yaw`.
  void set_body_pose(const RobotModel& model, const Pose& root, double x, double y, double yaw,
                     Eigen::VectorXd& q) const;
};

std::optional<MobileBase> find_mobile_base(const RobotModel& model);

// What a mobile base needs, in the user's terms, for `model` (read from `file`): "" when
// find_mobile_base finds one, else why the robot cannot be moved on the floor.
std::string mobile_base_problem(const RobotModel& model, const std::string& file);

}  // namespace demoplan
