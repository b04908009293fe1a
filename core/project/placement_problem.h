#pragma once
// The placement search's planning problem: a demonstration with the scene's robot stood at any
// base pose. A benchmark robot gets its support box made again for the new base; a cell's robot
// takes its pedestal along (robot_pedestal), or stands alone where it stood on a table or the
// floor.
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
