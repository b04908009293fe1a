#pragma once
// Process-wide cache of fitted FCL mesh BVHs (OBBRSS), and of the bounding spheres the
// collision checker's fast path tests first (fitted to the same scaled mesh, at the same time).
//
// Fitting a BVH is the costly part of building a CollisionChecker, and a process builds many
// checkers of the same meshes: planner, validator, every reload of a scene. Each distinct mesh
// is therefore fitted once per process and shared, immutable, by every checker and thread (as
// Pinocchio shares its Model). The key is the mesh's content with the scale applied (vertices
// bit for bit, triangles), not its file or its TriangleMesh object: a scene loaded a second time
// hits the cache, a mesh without a path works, and an edited file is fitted anew.
// Entries are kept for the life of the process; a process uses a bounded set of robot, object
// and furniture meshes.
#include <Eigen/Core>
#include <cstddef>
#include <memory>
#include <utility>
#include <vector>

#include "core/model/mesh.h"
#include "core/scene/bounding_spheres.h"

namespace fcl {
template <typename S>
class CollisionObject;
}  // namespace fcl

namespace demoplan {

// A collision object at the identity holding the mesh's shared BVH. Copy it and set the copy's
// transform: copying leaves the geometry untouched, whereas constructing an fcl::CollisionObject
// rewrites the geometry's local AABB, a write that would race with other threads' queries.
// Thread-safe; concurrent requests for the same mesh wait for one fit.
std::shared_ptr<const fcl::CollisionObject<double>> shared_mesh_bvh(const TriangleMesh& mesh,
                                                                    const Eigen::Vector3d& scale);

// A mesh's shared BVH (as shared_mesh_bvh) and the bounding spheres fitted with it (see
// bounding_spheres.h), both from one cache entry.
struct SharedMesh {
  std::shared_ptr<const fcl::CollisionObject<double>> bvh;
  std::shared_ptr<const SphereSet> spheres;
};
SharedMesh shared_mesh(const TriangleMesh& mesh, const Eigen::Vector3d& scale);

// Fits those of the meshes (with their scales) not in the cache yet, on up to `threads` threads,
// the largest first: a process's first checker has a dozen meshes to fit, about half a second
// on one core. A mesh that cannot be fitted is skipped; shared_mesh raises its error.
void fit_meshes(const std::vector<std::pair<const TriangleMesh*, Eigen::Vector3d>>& meshes, int threads);

// Number of BVHs fitted in this process so far.
std::size_t bvh_fits();

}  // namespace demoplan
