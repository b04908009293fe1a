#pragma once
// What the furniture covers of the floor, seen from above: per furniture item the convex hull of
// its collision geometry projected on the xy plane. The placement heat map draws them so the
// operator sees why a square is grey (the shelf is there).
#include <string>
#include <vector>

#include <Eigen/Core>

#include "core/scene/scene.h"

namespace demoplan {

struct Footprint {
  std::string name;
  std::vector<Eigen::Vector2d> outline;  // counter-clockwise, world x y (m)
};

// Every furniture item but the robot's support box or pedestal (they move with it) and the links
// the robot never meets (the tunnel's closing walls).
std::vector<Footprint> furniture_footprints(const Scene& scene);

}  // namespace demoplan
