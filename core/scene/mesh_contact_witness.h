#pragma once
// Proof that two triangle meshes touch as FCL sees them, without FCL's traversal: a pair of
// triangles, one of each mesh, that certainly cross. Robot self pairs such as the UR5's forearm
// against the hand, or its shoulder against the forearm, collide in most configurations where
// their bounds overlap, and each of those FCL calls walks two mesh trees (20-70 us); the
// triangles FCL found crossing at one relative pose of the two bodies mostly still cross at
// poses near it.
//
// A remembered pair is only a candidate: it is tested at the query's own poses every time, and
// answers "touching" only when an edge of one triangle crosses the other with room to spare
// (triangles_certainly_cross); otherwise the caller asks FCL, whose answer stays the answer.
#include <Eigen/Core>
#include <array>
#include <vector>

#include "core/scene/fcl_forward.h"

namespace demoplan {

// True only if the triangles p and q intersect as FCL's separating-axis test
// (Intersect::intersect_Triangle) sees them: an edge of one has its ends on either side of the
// other's plane, each farther than the margin, and crosses that plane inside the triangle,
// farther than the margin from each of its edges. The two then share a point with a margin of
// room around it in the plane and along the edge, so no axis separates them, however FCL
// rounds. Margin: 1 um plus 1e-9 of the farthest corner's distance from the origin, as for the
// bounding spheres.
bool triangles_certainly_cross(const std::array<Eigen::Vector3d, 3>& p,
                               const std::array<Eigen::Vector3d, 3>& q);

// Triangle pairs FCL found touching for one pair of meshes (FCL BVH models of triangles), each
// with the relative pose of the two bodies it was found at; one thread's, for one pair.
class MeshContactWitnesses {
public:
  // True only if a pair remembered near the bodies' current relative pose certainly crosses.
  bool prove(const fcl::CollisionObject<double>& a, const fcl::CollisionObject<double>& b);
  // After FCL found the bodies touching at triangle ta of a and tb of b: remembered when the
  // two certainly cross (FCL reports the first pair it meets, which may only graze).
  void learn(const fcl::CollisionObject<double>& a, int ta, const fcl::CollisionObject<double>& b, int tb);

  // Remembered pairs (a pair that proves moves to the front, a new one goes in the middle and
  // the last is dropped: deep crossings that prove over wide ranges of poses stay), how near a
  // pose must be to try its pair (three points of b's bounding sphere, none moved farther than
  // this in a's frame), and how many near pairs one query tries. Measured on the UR5's random
  // configurations (bench_collision, docs/benchmarks.md).
  static constexpr int kCapacity = 256;
  static constexpr double kNear = 0.05;
  static constexpr int kTries = 8;

private:
  struct Witness {
    int ta = -1, tb = -1;
    std::array<Eigen::Vector3f, 3> pose;  // b's three points in a's frame when it was found
  };
  std::vector<Witness> witnesses_;
};

}  // namespace demoplan
