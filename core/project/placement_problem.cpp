#include "core/project/placement_problem.h"

#include "core/error.h"
#include "core/placement/base_clearance.h"
#include "core/project/benchmark_instance.h"

namespace demoplan {

ProblemAtBase problem_at_base(std::shared_ptr<const Scene> scene, std::shared_ptr<const Demonstration> demonstration,
                              std::optional<BenchmarkRobot> robot) {
  if (!scene->robot.fixed_base)
    throw InputError(robot ? robot->urdf : scene->name, robot ? "robot_type" : "robot.mobile",
                     scene->robot.name + " is mobile: it drives to each pick, there is no base to place");
  // A cell's robot on a pedestal (furniture under its base that no part rests on) takes the
  // pedestal along; a table the parts rest on stays where it is.
  const int pedestal = robot ? -1 : robot_pedestal(*scene);
  return [scene, demonstration, robot, pedestal](const Pose& base) {
    Scene moved = *scene;
    if (robot) {
      move_benchmark_robot(moved, *robot, base);
    } else {
      const Pose shift = base * scene->robot.base.inverse();
      if (pedestal >= 0)
        for (Pose& link : moved.furniture[static_cast<size_t>(pedestal)].link_poses) link = shift * link;
      moved.robot.base = base;
    }
    return make_benchmark_instance(std::make_shared<const Scene>(std::move(moved)), *demonstration).problem;
  };
}

}  // namespace demoplan
