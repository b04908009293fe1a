#pragma once
// Does a fixed robot's base fit where it stands? The benchmark never checks a fixed robot's base
// (its root link and the links rigid to it) or its support box against the furniture: all of
// them are fixed to the world, placed by hand. A robot stood somewhere new by the placement
// search must be: a base inside the shelf, or a pedestal through the table's edge, is no base.
#include <string>

#include "core/scene/scene.h"

namespace demoplan {

// "" when the base and its support box are clear of every furniture item, else which part of
// the base meets which furniture. Both are lifted `lift` (m) first: a base standing on a table
// top touches it.
std::string base_clearance(const Scene& scene, double lift = 0.005);

}  // namespace demoplan
