#pragma once
// A demonstration measured from video puts resting parts a millimetre into or above their
// support, or tilted a fraction of a degree: enough for the planner to find the start in
// collision. Settling moves every world pose that nearly rests on a furniture support onto it
// (rest_pose.h's snap), or onto a moving support given per event (a tray) when there is none
// that near or the moving one is nearer; poses far from any support, or on a robot link, are
// kept as they are.
// Parts are matched to the scene's objects by id; a part the scene lacks is kept as it is.
#include "core/demo/demonstration.h"
#include "core/demo/rest_pose.h"
#include "core/scene/scene.h"

namespace demoplan {

struct SettleOptions {
  // Within ~6 degrees and 2 cm of a support.
  SnapOptions snap{.max_tilt = 0.1, .max_distance = 0.02, .gap = 0.001, .max_outside = 0.0, .viewpoint = {}};
  // A part on no furniture support is settled on a moving one (a tray's top) from this far: a
  // small part's height there is measured from its image alone, centimetres off a few metres
  // away; that its middle's line of sight meets the top inside it is what tells it rests there.
  double moving_max_distance = 0.06;
};

// Supports that move during the demonstration (the top of a tray the demonstrator carries),
// per event: world polygons where they were at the event's frame.
using EventSupports = std::vector<std::vector<std::vector<Eigen::Vector3d>>>;

Demonstration settle_on_supports(const Scene& scene, Demonstration demonstration, const SettleOptions& options = {},
                                 const EventSupports& moving = {});

}  // namespace demoplan
