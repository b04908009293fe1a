#pragma once
// A rigid motion in the horizontal plane: a turn about the vertical through a centre, plus a
// shift (whose z moves heights alike), as a tray or a board carries what stands on it. The
// world's z points up. Fitted by least squares to matched points: the synthetic videos animate
// a tray ride with it, the model tracker predicts where a part rode with others.
#include <vector>

#include "core/geometry/se3.h"

namespace demoplan {

struct PlanarMotion {
  Eigen::Vector3d centre = Eigen::Vector3d::Zero(), shift = Eigen::Vector3d::Zero();
  double yaw = 0.0;  // rad, about the vertical through `centre`
  Pose at(double s) const;  // the fraction s of the motion (0: none, 1: all of it)
};

// Takes the centroid of `from` to that of `to` and turns about it to fit them best (equal
// sizes; one point: no turn). Empty or unequal lists: no motion.
PlanarMotion fit_planar_motion(const std::vector<Eigen::Vector3d>& from, const std::vector<Eigen::Vector3d>& to);

}  // namespace demoplan
