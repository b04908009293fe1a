#pragma once
// Triangle meshes read from disk with assimp, in the units of the file (apply the URDF scale).
#include <Eigen/Geometry>
#include <array>
#include <memory>
#include <mutex>
#include <string>
#include <unordered_map>
#include <vector>

namespace demoplan {

struct TriangleMesh {
  std::string path;
  std::vector<Eigen::Vector3f> vertices;
  std::vector<Eigen::Vector3f> normals;           // per vertex; empty if the file has none
  std::vector<Eigen::Vector2f> uvs;               // per vertex; empty if untextured
  std::vector<std::array<std::uint32_t, 3>> triangles;
  std::string texture_path;                       // diffuse texture, absolute; empty if none
  Eigen::Vector4f color{0.8f, 0.8f, 0.8f, 1.0f};  // diffuse colour of the first material

  Eigen::AlignedBox3f bounds() const;
};

// Loads every mesh of the file, node transforms applied, into one triangle soup.
// Throws InputError naming the file when it is missing, unreadable or has no triangles.
std::shared_ptr<const TriangleMesh> load_mesh(const std::string& path);

// Shares meshes between models that reference the same file. Thread-safe.
class MeshCache {
public:
  std::shared_ptr<const TriangleMesh> get(const std::string& path);

private:
  std::mutex mutex_;
  std::unordered_map<std::string, std::shared_ptr<const TriangleMesh>> meshes_;
};

}  // namespace demoplan
