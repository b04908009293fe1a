#pragma once
// Random resting poses of an object on the scene's fixed supports: one of the object's contact
// polygons flat on a support polygon, anywhere on it, any rotation about its normal. These are
// the placements a manipulation planner without a demonstration explores.
#include <optional>
#include <random>
#include <vector>

#include "core/scene/support.h"

namespace demoplan {

class RestingPoseSampler {
public:
  explicit RestingPoseSampler(const Scene& scene, PlacementTolerance tolerance = {});

  // A world pose of `object` that passes the benchmark's placement test (check_placement), or
  // nothing when `attempts` draws all missed (the face overhangs the support, say). Collisions
  // with other bodies are the caller's to check.
  std::optional<Pose> sample(int object, std::mt19937_64& rng, int attempts = 20) const;

  bool empty() const { return supports_.empty(); }

private:
  struct Face {
    Eigen::Vector3d origin, normal;  // object frame; normal pointing away from the object's origin
  };
  struct Support {
    PolygonPlane plane;
    std::vector<Eigen::Vector2d> corners;  // in (u, v)
    Eigen::Vector2d lo, hi;                // bounding box in (u, v)
    double area = 0.0;
  };

  const Scene& scene_;
  PlacementTolerance tolerance_;
  std::vector<SupportPolygon> polygons_;  // furniture only: world-fixed
  std::vector<Support> supports_;
  std::vector<std::vector<Face>> faces_;  // per object
};

}  // namespace demoplan
