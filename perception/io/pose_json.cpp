#include "perception/io/pose_json.h"

namespace demoplan::perception {

Json pose_to_json(const Pose& pose) {
  const Eigen::Quaterniond q(pose.linear());
  const Eigen::Vector3d t = pose.translation();
  return Json{{"t", {t.x(), t.y(), t.z()}}, {"q", {q.x(), q.y(), q.z(), q.w()}}};
}

Pose pose_from_json(const JsonField& field) {
  if (field.value().is_array()) return field.pose();
  if (!field.value().is_object()) field.fail("must be {\"t\":[x,y,z],\"q\":[qx,qy,qz,qw]} or a 4x4 matrix");
  const JsonField t = field["t"], q = field["q"];
  if (t.size() != 3) t.fail("must hold 3 numbers");
  if (q.size() != 4) q.fail("must hold 4 numbers (qx, qy, qz, qw)");
  const Eigen::Quaterniond quat(q[3].number(), q[0].number(), q[1].number(), q[2].number());
  if (quat.norm() < 1e-9) q.fail("is not a rotation (zero quaternion)");
  if (std::abs(quat.norm() - 1.0) > 1e-3) q.fail("must be a unit quaternion (norm " + std::to_string(quat.norm()) + ")");
  return pose_from_xyz_quat({t[0].number(), t[1].number(), t[2].number()}, quat);
}

}  // namespace demoplan::perception
