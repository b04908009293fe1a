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
// A cell's pedestal (robot_pedestal) counts as part of the base. A base without a support box
// must also stand on something: the floor or the top of a piece of
// furniture under its origin (within `lift`).
std::string base_clearance(const Scene& scene, double lift = 0.005);

// The furniture whose top is at the robot's base height (within `tolerance`) under the base's
// origin, not counting a support box: what the robot stands on; -1 for the floor or nothing.
int furniture_under_base(const Scene& scene, double tolerance = 0.005);

// The pedestal the robot stands on and that moves with it: the furniture under its base that no
// part rests on (no support surfaces); -1 when there is none (the floor, a table, a support box).
int robot_pedestal(const Scene& scene);

}  // namespace demoplan
