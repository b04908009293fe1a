#include "core/model/kinematics.h"

#include <cassert>

namespace demoplan {

Pose joint_motion(const Joint& joint, double value) {
  Pose M = Pose::Identity();
  switch (joint.type) {
    case JointType::Revolute:
    case JointType::Continuous:
      M.linear() = Eigen::AngleAxisd(value, joint.axis).toRotationMatrix();
      break;
    case JointType::Prismatic: M.translation() = value * joint.axis; break;
    case JointType::Fixed: break;
  }
  return M;
}

namespace {
// parent * origin * joint_motion, without the product's work on the motion's zero parts (the
// same numbers: a turn leaves the translation as it is, a slide the rotation).
Pose child_pose(const Joint& j, const Pose& parent, const Eigen::VectorXd& q) {
  Pose T = parent * j.origin;
  if (j.q_index < 0) return T;
  const double value = q[j.q_index];
  switch (j.type) {
    case JointType::Revolute:
    case JointType::Continuous:
      T.linear() = T.linear() * Eigen::AngleAxisd(value, j.axis).toRotationMatrix();
      break;
    case JointType::Prismatic: T.translation() += T.linear() * (value * j.axis); break;
    case JointType::Fixed: break;
  }
  return T;
}
}  // namespace

void forward_kinematics(const RobotModel& model, const Eigen::VectorXd& q, const Pose& base,
                        PoseVector& link_poses) {
  assert(q.size() == model.nq);
  link_poses.resize(model.links.size());
  link_poses[0] = base;
  // Joints are stored depth-first, so a joint's parent link is always computed before it.
  for (const Joint& j : model.joints) link_poses[j.child_link] = child_pose(j, link_poses[j.parent_link], q);
}

Pose link_pose(const RobotModel& model, const Eigen::VectorXd& q, const Pose& base, int link) {
  std::vector<int> chain;
  for (int l = link; model.links[l].parent_joint >= 0;
       l = model.joints[model.links[l].parent_joint].parent_link)
    chain.push_back(model.links[l].parent_joint);
  Pose T = base;
  for (auto it = chain.rbegin(); it != chain.rend(); ++it) T = child_pose(model.joints[*it], T, q);
  return T;
}

}  // namespace demoplan
