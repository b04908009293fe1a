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
#include <string>
#include <utility>
#include <vector>

#include "core/model/mesh.h"
#include "core/scene/bounding_spheres.h"
#include "core/scene/fcl_forward.h"

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

// The shared mesh of each input (with its scale), in input order. Those not in the cache yet are
// fitted on up to `threads` threads, the largest first: a process's first checker has a dozen
// meshes to fit, about half a second on one core. Each mesh is scaled and hashed once; when all
// are cached no thread is started. A mesh that cannot be fitted raises its error (the first
// such in input order) after the others are done.
std::vector<SharedMesh> shared_meshes(const std::vector<std::pair<const TriangleMesh*, Eigen::Vector3d>>& meshes,
                                      int threads);

// The mesh's vertices with the scale applied, in double precision: what is fitted.
std::vector<Eigen::Vector3d> scaled_vertices(const TriangleMesh& mesh, const Eigen::Vector3d& scale);

// Meshes are also kept in `folder` between runs (fitted_mesh_store.h): a mesh fitted is
// stored there, a mesh stored there is read instead of fitted. "" (the default): no folder.
// The tools set default_fitted_mesh_folder() at their start (keep_meshes_between_runs).
void set_fitted_mesh_folder(const std::string& folder);
// Parsed mesh files (mesh_store.h) and fitted meshes kept in the user's cache folder: what each
// tool does at its start.
void keep_meshes_between_runs();

// Number of meshes fitted in this process so far, and read from the folder instead.
std::size_t bvh_fits();
std::size_t bvh_reads();

}  // namespace demoplan
