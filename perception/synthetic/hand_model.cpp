#include "perception/synthetic/hand_model.h"

namespace demoplan::perception {

RenderMesh hand_mesh() {
  const cv::Vec3f skin(140, 170, 215);  // BGR
  RenderMesh hand = box_mesh({0.10, 0.085, 0.03}, skin);
  Pose T = Pose::Identity();
  T.translation() << 0.0, 0.055, 0.02;  // thumb beside the palm, bent towards the part
  T.linear() = Eigen::AngleAxisd(0.5, Eigen::Vector3d::UnitX()).toRotationMatrix();
  hand.append(box_mesh({0.06, 0.025, 0.025}, skin), T);
  T = Pose::Identity();
  T.linear() = Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitY()).toRotationMatrix();
  T.translation() << -0.05 - 0.17, 0.0, -0.005;
  hand.append(cylinder_mesh(0.035, 0.34, skin), T);
  hand.color = skin;
  return hand;
}

}  // namespace demoplan::perception
