#include "core/model/mobile_base.h"

#include <cmath>
#include <vector>

#include "core/model/kinematics.h"

namespace demoplan {

namespace {

// The joint's axis in the root frame, with every joint before it at zero.
Eigen::Vector3d root_axis(const RobotModel& model, const Joint& joint) {
  const Pose parent = link_pose(model, Eigen::VectorXd::Zero(model.nq), Pose::Identity(), joint.parent_link);
  return (parent.linear() * joint.origin.linear() * joint.axis).normalized();
}

double planar_yaw(const Eigen::Matrix3d& R) { return std::atan2(R(1, 0), R(0, 0)); }

}  // namespace

std::optional<MobileBase> find_mobile_base(const RobotModel& model) {
  if (model.links.empty()) return std::nullopt;
  std::vector<const Joint*> moving;
  int link = 0;
  // Down the chain while the links carry nothing to collide with.
  while (model.links[link].collisions.empty() && model.links[link].child_joints.size() == 1) {
    const Joint& j = model.joints[model.links[link].child_joints.front()];
    if (j.q_index >= 0) moving.push_back(&j);
    link = j.child_link;
  }
  if (moving.size() != 3 || model.links[link].collisions.empty()) return std::nullopt;
  const Eigen::Vector3d up = Eigen::Vector3d::UnitZ();
  const Eigen::Vector3d ax = root_axis(model, *moving[0]), ay = root_axis(model, *moving[1]);
  const Eigen::Vector3d az = root_axis(model, *moving[2]);
  const bool planar = moving[0]->type == JointType::Prismatic && moving[1]->type == JointType::Prismatic &&
                      moving[2]->type != JointType::Prismatic && std::abs(ax.dot(up)) < 1e-6 &&
                      std::abs(ay.dot(up)) < 1e-6 && ax.cross(ay).norm() > 0.5 && std::abs(az.dot(up)) > 1 - 1e-6;
  if (!planar) return std::nullopt;
  MobileBase b;
  b.x = moving[0]->q_index;
  b.y = moving[1]->q_index;
  b.yaw = moving[2]->q_index;
  b.body = link;
  b.yaw_sign = az.z() > 0 ? 1.0 : -1.0;
  return b;
}

std::string mobile_base_problem(const RobotModel& model, const std::string& file) {
  if (find_mobile_base(model)) return "";
  return file + " has no planar base joints: a mobile base needs its root link followed by two prismatic joints "
                "along horizontal axes and a revolute joint about the vertical (x, y, yaw), through links without "
                "collision geometry, then the base body";
}

Pose MobileBase::body_pose(const RobotModel& model, const Eigen::VectorXd& q, const Pose& root) const {
  return link_pose(model, q, root, body);
}

void MobileBase::set_body_pose(const RobotModel& model, const Pose& root, double x, double y, double yaw,
                               Eigen::VectorXd& q) const {
  // The prismatic joints come before the yaw: the body's yaw depends on the yaw slot alone, and
  // its position is affine in the two prismatic slots once the yaw is set.
  q[this->x] = q[this->y] = q[this->yaw] = 0.0;
  const double yaw0 = planar_yaw(body_pose(model, q, root).linear());
  q[this->yaw] = std::remainder(yaw_sign * (yaw - yaw0), 2 * M_PI);
  const Eigen::Vector3d p0 = body_pose(model, q, root).translation();
  q[this->x] = 1.0;
  const Eigen::Vector3d px = body_pose(model, q, root).translation() - p0;
  q[this->x] = 0.0;
  q[this->y] = 1.0;
  const Eigen::Vector3d py = body_pose(model, q, root).translation() - p0;
  Eigen::Matrix2d A;
  A << px.x(), py.x(), px.y(), py.y();
  const Eigen::Vector2d s = A.inverse() * Eigen::Vector2d(x - p0.x(), y - p0.y());
  q[this->x] = s[0];
  q[this->y] = s[1];
}

}  // namespace demoplan
