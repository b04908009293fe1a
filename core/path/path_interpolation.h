#pragma once
// A Path as a continuous motion, t in [0, 1] proportional to the robot's joint-space length:
// the robot moves linearly between waypoints; an object that keeps its pose relative to a robot
// link across a segment (held by the gripper, riding on the deck) moves rigidly with that link,
// an object that keeps its world pose stays. Anything else moves without being carried: the
// interpolator interpolates it and says so.
#include <vector>

#include "core/path/path.h"
#include "core/scene/scene.h"

namespace demoplan {

class PathInterpolator {
public:
  PathInterpolator(const Scene& scene, const Path& path);

  // The robot configuration and every object's world pose at parameter t.
  SceneState at(double t) const;
  // The scene with the robot at q anywhere on segment k (waypoints k, k+1), e.g. a timed
  // trajectory's blend near it: carried objects follow their link; u in [0, 1] places the
  // uncarried ones.
  SceneState on_segment(size_t k, const Eigen::VectorXd& q, double u) const;
  double length() const { return total_; }
  // Parameter of waypoint k.
  double waypoint_parameter(size_t k) const { return total_ > 0 ? cumulative_[k] / total_ : 0.0; }
  // Where the path is checked: the benchmark's grid t = k * delta (numpy.arange(0, 1 + delta,
  // delta), capped at 1) plus enough points per segment that consecutive samples are at most
  // `max_step` apart in joint space. Sorted, without duplicates.
  std::vector<double> sample_parameters(double delta, double max_step) const;
  // Objects that move across a segment without keeping their pose to any robot link: a
  // teleport. Empty for a well-formed path; (segment, object) pairs otherwise.
  const std::vector<std::pair<int, int>>& uncarried() const { return uncarried_; }

private:
  struct ObjectMotion {
    int link = -1;  // -1: static (or uncarried: interpolated), else the robot link it rides
    Pose link_T_object = Pose::Identity();
  };
  const Scene& scene_;
  const Path& path_;
  std::vector<double> cumulative_;
  double total_ = 0.0;
  std::vector<std::vector<ObjectMotion>> motion_;  // [segment][object]
  std::vector<std::pair<int, int>> uncarried_;
};

}  // namespace demoplan
