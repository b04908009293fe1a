#pragma once
// The placement search's planning problem: a demonstration with the scene's robot stood at any
// base pose. A benchmark robot gets its support box made again for the new base; a cell's robot
// is moved alone (its pedestal is the user's, part of the robot or the furniture).
#include <memory>
#include <optional>

#include "core/demo/benchmark_scene.h"
#include "core/placement/base_placement.h"

namespace demoplan {

// `robot`: the benchmark robot's entry (footprint), absent for a cell. Throws InputError for a
// mobile robot (it drives to each pick: there is no base to place).
ProblemAtBase problem_at_base(std::shared_ptr<const Scene> scene, std::shared_ptr<const Demonstration> demonstration,
                              std::optional<BenchmarkRobot> robot);

}  // namespace demoplan
