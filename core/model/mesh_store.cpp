#include "core/model/mesh_store.h"

#include <cstring>
#include <filesystem>

#include "core/io/atomic_file.h"
#include "core/io/binary_file.h"
#include "core/io/user_cache.h"

namespace demoplan {

namespace fs = std::filesystem;

namespace {

constexpr char kMagic[8] = {'D', 'P', 'M', 'E', 'S', 'H', '0', '1'};

std::string file_of(const std::string& folder, const std::string& path) {
  char name[32];
  std::snprintf(name, sizeof name, "%016llx.mesh",
                static_cast<unsigned long long>(hash_bytes(path.data(), path.size())));
  return (fs::path(folder) / name).string();
}

CacheFolderSetting folder_of_meshes;

}  // namespace

MeshSource mesh_source(const std::string& file) {
  MeshSource s;
  s.file = file;
  std::string bytes;
  std::error_code ec;
  s.exists = fs::is_regular_file(file, ec) && read_whole_file(file, bytes);
  if (s.exists) {
    s.size = bytes.size();
    s.hash = hash_bytes(bytes.data(), bytes.size());
  }
  return s;
}

std::shared_ptr<const TriangleMesh> read_stored_mesh(const std::string& folder, const std::string& path) {
  if (folder.empty()) return nullptr;
  std::string bytes;
  if (!read_whole_file(file_of(folder, path), bytes)) return nullptr;
  ByteReader r{bytes.data(), bytes.data() + bytes.size()};
  char magic[8];
  std::uint64_t checksum = 0, sources = 0;
  if (!r.get(magic) || std::memcmp(magic, kMagic, sizeof magic) != 0 || !r.get(checksum) ||
      hash_bytes(r.at, r.left()) != checksum || !r.get(sources) || sources > 1000)
    return nullptr;
  // Each source as it was when the mesh was read, or the mesh is read again.
  for (std::uint64_t i = 0; i < sources; ++i) {
    MeshSource then;
    char exists = 0;
    if (!r.get_string(then.file) || !r.get(exists) || !r.get(then.size) || !r.get(then.hash)) return nullptr;
    const MeshSource now = mesh_source(then.file);
    if (now.exists != (exists != 0) || (now.exists && (now.size != then.size || now.hash != then.hash))) return nullptr;
  }
  auto mesh = std::make_shared<TriangleMesh>();
  if (!r.get_string(mesh->path) || mesh->path != path || !r.get_vector(mesh->vertices) || !r.get_vector(mesh->normals) ||
      !r.get_vector(mesh->uvs) || !r.get_vector(mesh->triangles) || !r.get_string(mesh->texture_path) ||
      !r.get(mesh->color) || r.at != r.end)
    return nullptr;
  for (const auto& t : mesh->triangles)
    for (std::uint32_t v : t)
      if (v >= mesh->vertices.size()) return nullptr;
  return mesh;
}

void store_mesh(const std::string& folder, const TriangleMesh& mesh, const std::vector<MeshSource>& sources) {
  if (folder.empty()) return;
  std::string body;
  put_bytes(body, static_cast<std::uint64_t>(sources.size()));
  for (const MeshSource& s : sources) {
    put_string(body, s.file);
    put_bytes(body, static_cast<char>(s.exists));
    put_bytes(body, s.size);
    put_bytes(body, s.hash);
  }
  put_string(body, mesh.path);
  put_vector(body, mesh.vertices);
  put_vector(body, mesh.normals);
  put_vector(body, mesh.uvs);
  put_vector(body, mesh.triangles);
  put_string(body, mesh.texture_path);
  put_bytes(body, mesh.color);
  std::string bytes(kMagic, sizeof kMagic);
  put_bytes(bytes, hash_bytes(body.data(), body.size()));
  bytes += body;
  try {
    std::error_code ec;
    fs::create_directories(folder, ec);
    write_file_atomic(file_of(folder, mesh.path), bytes);
  } catch (const std::exception&) {
    // A read-only or full disk: the mesh is simply read from its file again next time.
  }
}

void set_mesh_store_folder(const std::string& folder) { folder_of_meshes.set(folder); }

std::string mesh_store_folder() { return folder_of_meshes.get(); }

std::string default_mesh_store_folder() { return user_cache_folder("mesh-files"); }

}  // namespace demoplan
