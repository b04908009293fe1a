#include "perception/tracking/carrier_ride.h"

#include <cmath>

#include <Eigen/Dense>

namespace demoplan::perception {

namespace {

// The ride's motion: a turn by `p[0]` about the vertical through the carrier's centre before,
// then a shift by p[1..3].
Eigen::Vector3d moved(const Eigen::Vector4d& p, const Eigen::Vector3d& centre, const Eigen::Vector3d& x) {
  return centre + Eigen::Vector3d(p[1], p[2], p[3]) + Eigen::AngleAxisd(p[0], Eigen::Vector3d::UnitZ()) * (x - centre);
}

}  // namespace

RideFit fit_ride(const Camera& camera, const Pose& carrier_before, const Pose& carrier_after,
                 const std::vector<RiderSighting>& riders, const CarrierRideOptions& options) {
  RideFit fit;
  if (!camera.world_T_camera || static_cast<int>(riders.size()) < options.min_riders) return fit;
  const Pose camera_T_world = camera.world_T_camera->inverse();
  const auto pixel = [&](const Eigen::Vector3d& world) {
    const cv::Point2d q = camera.project(camera_T_world * world);
    return Eigen::Vector2d(q.x, q.y);
  };
  // The carrier's centre counts as a sighting: where its track shows it.
  std::vector<RiderSighting> points = riders;
  const Eigen::Vector3d centre = carrier_before.translation();
  points.push_back({centre, pixel(carrier_after.translation())});
  const auto residuals = [&](const Eigen::Vector4d& p) {
    Eigen::VectorXd r(2 * points.size());
    for (size_t i = 0; i < points.size(); ++i) {
      const Eigen::Vector3d x = moved(p, centre, points[i].before);
      if ((camera_T_world * x).z() <= 1e-3) return Eigen::VectorXd();  // behind the camera: no fit from here
      r.segment<2>(2 * i) = pixel(x) - points[i].seen;
    }
    return r;
  };

  // From the tracked motion, Gauss-Newton with a numeric Jacobian (a handful of points).
  const Eigen::Matrix3d turn = carrier_after.linear() * carrier_before.linear().transpose();
  Eigen::Vector4d p;
  p << std::atan2(turn(1, 0), turn(0, 0)), carrier_after.translation() - centre;
  Eigen::VectorXd r = residuals(p);
  if (r.size() == 0) return fit;
  for (int iteration = 0; iteration < 20; ++iteration) {
    Eigen::MatrixXd J(r.size(), 4);
    for (int k = 0; k < 4; ++k) {
      Eigen::Vector4d d = Eigen::Vector4d::Zero();
      d[k] = 1e-5;  // rad or m
      const Eigen::VectorXd plus = residuals(p + d), minus = residuals(p - d);
      if (plus.size() == 0 || minus.size() == 0) return fit;
      J.col(k) = (plus - minus) / (2 * d[k]);
    }
    const Eigen::Vector4d step = (J.transpose() * J + 1e-9 * Eigen::Matrix4d::Identity()).ldlt().solve(-J.transpose() * r);
    p += step;
    r = residuals(p);
    if (r.size() == 0) return fit;
    if (step.tail<3>().norm() < 1e-6 && std::abs(step[0]) < 1e-7) break;
  }
  fit.residual_px = std::sqrt(r.squaredNorm() / static_cast<double>(points.size()));
  if (fit.residual_px > options.max_residual_px) return fit;

  Pose after = Pose::Identity();
  after.linear() = Eigen::AngleAxisd(p[0], Eigen::Vector3d::UnitZ()) * carrier_before.linear();
  after.translation() = moved(p, centre, centre);
  const Eigen::Vector3d eye = camera.world_T_camera->translation();
  const double tracked = (carrier_after.translation() - eye).norm();
  if (std::abs((after.translation() - eye).norm() - tracked) <= options.max_depth_change * tracked)
    fit.motion = after * carrier_before.inverse();
  return fit;
}

}  // namespace demoplan::perception
