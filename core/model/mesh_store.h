#pragma once
// Meshes as load_mesh reads them, kept on disk between runs. Parsing a mesh file with assimp is
// the largest part of loading a scene once its fitted meshes are kept (fitted_mesh_store.h):
// about 0.2 s of CPU for a robot and three YCB-V parts, where reading the result back takes
// milliseconds.
//
// A mesh depends on more than its file: an OBJ's materials, a glTF's buffers, a texture that
// exists or not. So every file assimp opened or asked about while reading it is recorded with
// its size and a hash of its content (or that it was missing), and a stored mesh is used only
// while each of them is still so. A file is named by a hash of the mesh's path.
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "core/model/mesh.h"

namespace demoplan {

// What a mesh was read from: a file and its state then.
struct MeshSource {
  std::string file;
  bool exists = false;
  std::uint64_t size = 0, hash = 0;  // of its content, when it exists
};
// The file's state now.
MeshSource mesh_source(const std::string& file);

// `folder`/<hash of path>.mesh when it holds the mesh of `path` and every source is unchanged;
// nullptr otherwise.
std::shared_ptr<const TriangleMesh> read_stored_mesh(const std::string& folder, const std::string& path);
// Written atomically (the folder created); a folder that cannot be written is skipped.
void store_mesh(const std::string& folder, const TriangleMesh& mesh, const std::vector<MeshSource>& sources);

// Where load_mesh keeps meshes in this process: "" (the default) none. The tools set
// default_mesh_store_folder() at their start; tests leave it unset.
void set_mesh_store_folder(const std::string& folder);
std::string mesh_store_folder();
// $XDG_CACHE_HOME/demoplan/mesh-files, else ~/.cache/demoplan/mesh-files.
std::string default_mesh_store_folder();

}  // namespace demoplan
