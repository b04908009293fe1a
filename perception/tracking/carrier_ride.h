#pragma once
// Where a ride took a carrier (a tray the demonstrator carries with parts standing on it), from
// where it and its riders show after it. Its depth from its own image is its weakest coordinate
// (waiter_0's tray 27 mm off along its line of sight 2.4 m away after its ride, and the parts
// settled onto its top took that over), but the parts spread over its top make a pattern whose
// size in the image holds the depth, and each part's place in the image is measured well even
// where its depth is not. The ride is one rigid motion that keeps the carrier level (a turn
// about the vertical and a shift), fitted to the image positions of the carrier's and its
// riders' centres after it, from their world positions before it.
#include <optional>
#include <vector>

#include <Eigen/Core>

#include "core/geometry/se3.h"
#include "perception/camera/camera_model.h"

namespace demoplan::perception {

// A rider's centre (world) before the ride and where the image shows it after (pixels).
struct RiderSighting {
  Eigen::Vector3d before;
  Eigen::Vector2d seen;
};

struct CarrierRideOptions {
  int min_riders = 2;               // one rider's place does not tell a turn from a shift
  double max_residual_px = 3.0;     // RMS over the centres: larger, they did not ride as one
  double max_depth_change = 0.05;   // of the carrier's distance: larger, the fit went astray
};

struct RideFit {
  // World: a pose after the ride is the motion times the pose before. None when the riders are
  // too few, or do not fit one motion (residual_px), or it went astray.
  std::optional<Pose> motion;
  double residual_px = -1.0;  // RMS over the centres; -1: not fitted (too few riders)
};

// The ride's motion that fits the sightings best, from the carrier's tracked pose after it,
// `carrier_after`, whose image position counts as a rider's.
RideFit fit_ride(const Camera& camera, const Pose& carrier_before, const Pose& carrier_after,
                 const std::vector<RiderSighting>& riders, const CarrierRideOptions& options = {});

}  // namespace demoplan::perception
