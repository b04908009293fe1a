#include "core/project/placement_problem.h"

#include "core/error.h"
#include "core/project/benchmark_instance.h"

namespace demoplan {

ProblemAtBase problem_at_base(std::shared_ptr<const Scene> scene, std::shared_ptr<const Demonstration> demonstration,
                              std::optional<BenchmarkRobot> robot) {
  if (!scene->robot.fixed_base)
    throw InputError(robot ? robot->urdf : scene->name, robot ? "robot_type" : "robot.mobile",
                     scene->robot.name + " is mobile: it drives to each pick, there is no base to place");
  return [scene, demonstration, robot](const Pose& base) {
    Scene moved = *scene;
    if (robot) move_benchmark_robot(moved, *robot, base);
    else moved.robot.base = base;
    return make_benchmark_instance(std::make_shared<const Scene>(std::move(moved)), *demonstration).problem;
  };
}

}  // namespace demoplan
