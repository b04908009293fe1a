#pragma once
// A found path collision-checked again where the benchmark samples it (t = k * delta along its
// length, plus enough points that no two are more than max_step apart): between a planner's
// edge samples a held object can clip an obstacle edge (PlannerParams::final_check).
#include <functional>

#include "core/path/path.h"
#include "core/scene/collision_checker.h"

namespace demoplan {

// The first segment (index of its first waypoint) with a collision at one of those samples, -1
// when there is none. `keep_going` is asked every 64 samples; when it says no, -1.
int first_colliding_segment(const Scene& scene, const CollisionChecker& checker, CollisionData& data,
                            const Path& path, double delta, double max_step,
                            const std::function<bool()>& keep_going);

}  // namespace demoplan
