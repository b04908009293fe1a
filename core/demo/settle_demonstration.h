#pragma once
// A demonstration measured from video puts resting parts a millimetre into or above their
// support, or tilted a fraction of a degree: enough for the planner to find the start in
// collision. Settling moves every world pose that nearly rests on a furniture support onto it
// (rest_pose.h's snap); poses far from any support, or on a robot link, are kept as they are.
#include "core/demo/demonstration.h"
#include "core/demo/rest_pose.h"
#include "core/scene/scene.h"

namespace demoplan {

struct SettleOptions {
  SnapOptions snap{0.1, 0.02, 0.001, 0.0};  // within ~6 degrees and 2 cm of a support
};

Demonstration settle_on_supports(const Scene& scene, Demonstration demonstration, const SettleOptions& options = {});

}  // namespace demoplan
