#pragma once
// Collision and distance queries for a Scene on FCL.
//
// Broad phase: the furniture sits in one FCL dynamic AABB tree built once; every moving
// geometry (robot links, objects) queries it. Moving-vs-moving pairs are listed once at
// construction and pruned per query by their world AABBs before the narrow phase. Each pair
// left is first tested on cheap exact bounds (CollisionOptions::fast_path): bounding spheres or
// the exact primitive, a self pair's distance table (joint_pair_table.h), a corner or an edge
// of one body inside the other primitive, and for two meshes a pair of their triangles FCL
// found crossing at a nearby pose (mesh_contact_witness.h); it goes to FCL's narrow phase only
// when they cannot decide.
// The checker is immutable after construction, but for the self pairs' distance tables, filled
// on demand by any thread; each thread passes its own CollisionData (which keeps the triangle
// pairs).
#include <Eigen/Core>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "core/scene/scene.h"

namespace demoplan {

// Pairs exempt from checking: a grasped object and the fingers, an object and the surface
// it rests on.
struct AllowedContacts {
  std::vector<std::pair<int, int>> object_link;       // (object, robot link)
  std::vector<std::pair<int, int>> object_furniture;  // (object, furniture)

  void allow_object_link(int object, int link) { object_link.emplace_back(object, link); }
  void allow_object_furniture(int object, int furniture) {
    object_furniture.emplace_back(object, furniture);
  }
  // The object and every robot link from the gripper link down (hand and fingers).
  void allow_gripper(const Scene& scene, int object);
  bool allows_object_link(int object, int link) const;
  bool allows_object_furniture(int object, int furniture) const;
};

// Two bodies that touch, named "robot/<link>", "object/<id>" or "<furniture>/<link>".
struct CollisionPair {
  std::string first;
  std::string second;
};

struct DistanceResult {
  double distance = 0.0;  // metres; 0 when in collision
  CollisionPair pair;
  Eigen::Vector3d first_point = Eigen::Vector3d::Zero();  // world, on pair.first
  Eigen::Vector3d second_point = Eigen::Vector3d::Zero();
};

struct CollisionOptions {
  // Skip robot links joined by one moving joint (besides the SRDF's disabled pairs).
  bool skip_adjacent_links = true;
  // Before FCL's narrow phase, test the pair's bounds (spheres fitted to meshes, exact boxes,
  // cylinders and spheres, self pairs' distance tables) and skip FCL when they are certainly
  // apart, or certainly touching (a corner or an edge inside a primitive; geometry_bounds.h).
  // Answers and reported pairs are the same either way; off: FCL alone, for comparison.
  bool fast_path = true;
};

// Per-thread workspace of a checker: FCL objects at this query's poses, request and result.
class CollisionData {
public:
  CollisionData();
  ~CollisionData();
  CollisionData(CollisionData&&) noexcept;
  CollisionData& operator=(CollisionData&&) noexcept;

  struct Workspace;  // defined in the .cpp: FCL stays out of this header

private:
  friend class CollisionChecker;
  std::unique_ptr<Workspace> w_;
};

class CollisionChecker {
public:
  // Keeps a reference to the scene, which must outlive the checker.
  explicit CollisionChecker(const Scene& scene, CollisionOptions options = {});
  ~CollisionChecker();
  CollisionChecker(const CollisionChecker&) = delete;
  CollisionChecker& operator=(const CollisionChecker&) = delete;

  CollisionData make_data() const;

  // True at the first colliding pair; `hit` (optional) names it.
  bool in_collision(const SceneState& state, CollisionData& data,
                    const AllowedContacts& allowed = {}, CollisionPair* hit = nullptr) const;
  // Every colliding pair, for diagnostics and the UI.
  std::vector<CollisionPair> collisions(const SceneState& state, CollisionData& data,
                                        const AllowedContacts& allowed = {}) const;
  // Smallest distance between any two bodies that are checked against each other.
  DistanceResult distance(const SceneState& state, CollisionData& data,
                          const AllowedContacts& allowed = {}) const;
  // Smallest distance between one object and anything it is checked against.
  DistanceResult object_distance(const SceneState& state, CollisionData& data, int object,
                                 const AllowedContacts& allowed = {}) const;

  // Number of geometry pairs a full check considers (before any pruning).
  size_t pair_count() const;
  const Scene& scene() const { return scene_; }

  struct Impl;

private:
  DistanceResult min_distance(const SceneState& state, CollisionData& data,
                              const AllowedContacts& allowed, int only_object) const;
  const Scene& scene_;
  std::unique_ptr<Impl> impl_;
};

}  // namespace demoplan
