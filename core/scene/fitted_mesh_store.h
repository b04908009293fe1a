#pragma once
// Fitted meshes kept on disk between runs. Fitting a scene's meshes (FCL's OBBRSS tree and our
// bounding spheres) is most of what loading a scene costs, about half a second of CPU for a
// robot, a shelf and three YCB-V parts, and a `plan` or `check` process pays it on every start.
//
// FCL builds its tree by asking a fitter for each node's volume, depth first, and splits each
// node by that volume; its API cannot take stored nodes. So the fitter's answers are recorded
// while the tree is fitted, and replayed to build it again: the same volumes in the same order
// give the same splits and the same tree, bit for bit, without fitting (a replay that does not
// match the mesh's node counts is refused and the mesh fitted).
//
// A file is named by the scaled mesh's content (two independent 64-bit hashes) and holds the
// format's version, FCL's version, the mesh's counts and a checksum of everything after the
// header: a file that does not answer to all of them is not used. These bounds decide what the
// checker calls free, so nothing less than an exact match is read.
#include <fcl/geometry/bvh/BVH_model.h>
#include <fcl/math/bv/OBBRSS.h>

#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/scene/bounding_spheres.h"

namespace demoplan {

// The fitter's answers for one tree: node volumes in the order FCL asked for them, and the
// number of triangles each was fitted to.
struct RecordedFit {
  std::vector<int> counts;
  std::vector<fcl::OBBRSSd> volumes;
};

// A mesh as the collision checker needs it, fitted.
struct FittedMesh {
  RecordedFit tree;
  SphereSet spheres;
};

// The identity of a scaled mesh: its vertices (bit for bit) and triangles.
struct MeshKey {
  std::uint64_t hash_a = 0, hash_b = 0;
  std::uint64_t vertices = 0, triangles = 0;
};
MeshKey mesh_key(const std::vector<Eigen::Vector3d>& vertices, const std::vector<std::array<std::uint32_t, 3>>& triangles);

// FCL's OBBRSS tree of the triangles: fitted, the fitter's answers recorded into `record` when
// given; or, with `replay`, built from those answers without fitting (nullptr when they do not
// match the triangles).
std::shared_ptr<fcl::BVHModel<fcl::OBBRSSd>> build_obbrss_tree(const std::vector<Eigen::Vector3d>& vertices,
                                                               const std::vector<std::array<std::uint32_t, 3>>& triangles,
                                                               const RecordedFit* replay = nullptr,
                                                               RecordedFit* record = nullptr);

// `folder`/<key>.fit; nullopt when missing, damaged, of another format or FCL version, or not
// of this mesh.
std::optional<FittedMesh> read_fitted_mesh(const std::string& folder, const MeshKey& key);
// Written atomically (the folder created); a folder that cannot be written is skipped: the
// store only saves time.
void write_fitted_mesh(const std::string& folder, const MeshKey& key, const FittedMesh& mesh);

// Where the tools keep them: $XDG_CACHE_HOME/demoplan/meshes, else ~/.cache/demoplan/meshes
// ("" without either variable).
std::string default_fitted_mesh_folder();

}  // namespace demoplan
