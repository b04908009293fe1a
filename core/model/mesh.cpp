#include "core/model/mesh.h"

#include <assimp/DefaultIOSystem.h>
#include <assimp/Importer.hpp>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <algorithm>
#include <filesystem>

#include "core/error.h"
#include "core/model/mesh_store.h"

namespace demoplan {

Eigen::AlignedBox3f TriangleMesh::bounds() const {
  Eigen::AlignedBox3f box;
  for (const auto& v : vertices) box.extend(v);
  return box;
}

namespace {

void append_node(const aiScene* scene, const aiNode* node, const aiMatrix4x4& parent,
                 TriangleMesh& out) {
  const aiMatrix4x4 T = parent * node->mTransformation;
  aiMatrix3x3 R(T);
  R.Inverse().Transpose();  // normals transform with the inverse transpose
  for (unsigned m = 0; m < node->mNumMeshes; ++m) {
    const aiMesh* mesh = scene->mMeshes[node->mMeshes[m]];
    const auto base = static_cast<std::uint32_t>(out.vertices.size());
    for (unsigned i = 0; i < mesh->mNumVertices; ++i) {
      const aiVector3D v = T * mesh->mVertices[i];
      out.vertices.emplace_back(v.x, v.y, v.z);
      if (mesh->HasNormals()) {
        aiVector3D n = R * mesh->mNormals[i];
        n.Normalize();
        out.normals.emplace_back(n.x, n.y, n.z);
      }
      if (mesh->HasTextureCoords(0)) {
        out.uvs.emplace_back(mesh->mTextureCoords[0][i].x, mesh->mTextureCoords[0][i].y);
      }
    }
    for (unsigned f = 0; f < mesh->mNumFaces; ++f) {
      const aiFace& face = mesh->mFaces[f];
      if (face.mNumIndices != 3) continue;  // points and lines carry no volume
      out.triangles.push_back({base + face.mIndices[0], base + face.mIndices[1],
                               base + face.mIndices[2]});
    }
  }
  for (unsigned c = 0; c < node->mNumChildren; ++c) append_node(scene, node->mChildren[c], T, out);
}

// `looked_at`: the texture file it looked for, if any.
void read_material(const aiScene* scene, const std::filesystem::path& dir, TriangleMesh& out, std::string& looked_at) {
  for (unsigned m = 0; m < scene->mNumMeshes; ++m) {
    const aiMaterial* mat = scene->mMaterials[scene->mMeshes[m]->mMaterialIndex];
    aiColor4D c;
    if (mat->Get(AI_MATKEY_COLOR_DIFFUSE, c) == AI_SUCCESS) out.color = {c.r, c.g, c.b, c.a};
    aiString tex;
    if (mat->GetTexture(aiTextureType_DIFFUSE, 0, &tex) == AI_SUCCESS) {
      const auto p = dir / tex.C_Str();
      looked_at = p.string();
      if (std::filesystem::exists(p)) out.texture_path = p.string();
    }
    return;
  }
}

// assimp's own file access, each file it opens or asks about noted: what a mesh was read from.
class NotingIOSystem final : public Assimp::DefaultIOSystem {
public:
  bool Exists(const char* file) const override {
    note(file);
    return DefaultIOSystem::Exists(file);
  }
  Assimp::IOStream* Open(const char* file, const char* mode) override {
    note(file);
    return DefaultIOSystem::Open(file, mode);
  }
  const std::vector<std::string>& files() const { return files_; }

private:
  void note(const char* file) const {
    if (std::find(files_.begin(), files_.end(), file) == files_.end()) files_.emplace_back(file);
  }
  mutable std::vector<std::string> files_;
};

std::shared_ptr<const TriangleMesh> parse_mesh(const std::string& path, std::vector<std::string>* sources) {
  Assimp::Importer importer;
  auto* io = new NotingIOSystem;  // the importer owns it
  importer.SetIOHandler(io);
  // URDF meshes are expressed in the link frame: do not let the Collada reader re-orient them.
  importer.SetPropertyBool(AI_CONFIG_IMPORT_COLLADA_IGNORE_UP_DIRECTION, true);
  const aiScene* scene = importer.ReadFile(
      path, aiProcess_Triangulate | aiProcess_JoinIdenticalVertices | aiProcess_SortByPType);
  if (!scene || !scene->mRootNode) {
    throw InputError(path, "", std::string("cannot read mesh: ") + importer.GetErrorString());
  }
  auto mesh = std::make_shared<TriangleMesh>();
  mesh->path = path;
  append_node(scene, scene->mRootNode, aiMatrix4x4(), *mesh);
  if (mesh->triangles.empty()) throw InputError(path, "", "mesh has no triangles");
  if (mesh->normals.size() != mesh->vertices.size()) mesh->normals.clear();
  if (mesh->uvs.size() != mesh->vertices.size()) mesh->uvs.clear();
  std::string texture;
  read_material(scene, std::filesystem::path(path).parent_path(), *mesh, texture);
  if (sources) {
    *sources = io->files();
    if (!texture.empty()) sources->push_back(texture);
  }
  return mesh;
}

}  // namespace

std::shared_ptr<const TriangleMesh> load_mesh(const std::string& path) {
  if (!std::filesystem::exists(path)) throw InputError(path, "", "mesh file not found");
  const std::string folder = mesh_store_folder();
  if (folder.empty()) return parse_mesh(path, nullptr);
  if (auto stored = read_stored_mesh(folder, path)) return stored;
  std::vector<std::string> files;
  auto mesh = parse_mesh(path, &files);
  std::vector<MeshSource> sources;
  for (const auto& f : files) sources.push_back(mesh_source(f));
  store_mesh(folder, *mesh, sources);
  return mesh;
}

std::shared_ptr<const TriangleMesh> MeshCache::get(const std::string& path) {
  const std::string key = std::filesystem::weakly_canonical(path).string();
  {
    std::lock_guard lock(mutex_);
    if (auto it = meshes_.find(key); it != meshes_.end()) return it->second;
  }
  auto mesh = load_mesh(path);  // outside the lock: loading can take a while
  std::lock_guard lock(mutex_);
  return meshes_.emplace(key, std::move(mesh)).first->second;
}

}  // namespace demoplan
