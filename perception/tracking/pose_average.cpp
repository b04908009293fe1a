#include "perception/tracking/pose_average.h"

#include <algorithm>

namespace demoplan::perception {

Eigen::Matrix3d mean_rotation(const std::vector<Eigen::Matrix3d>& rotations) {
  Eigen::Matrix3d sum = Eigen::Matrix3d::Zero();
  for (const auto& R : rotations) sum += R;
  const Eigen::JacobiSVD<Eigen::Matrix3d> svd(sum, Eigen::ComputeFullU | Eigen::ComputeFullV);
  Eigen::Matrix3d U = svd.matrixU();
  if ((U * svd.matrixV().transpose()).determinant() < 0) U.col(2) *= -1;
  return U * svd.matrixV().transpose();
}

Pose mean_pose(const PoseList& poses) {
  Pose out = Pose::Identity();
  std::vector<Eigen::Matrix3d> R;
  Eigen::Vector3d t = Eigen::Vector3d::Zero();
  for (const auto& p : poses) {
    R.push_back(p.linear());
    t += p.translation();
  }
  out.linear() = mean_rotation(R);
  out.translation() = t / static_cast<double>(std::max<size_t>(1, poses.size()));
  return out;
}

}  // namespace demoplan::perception
