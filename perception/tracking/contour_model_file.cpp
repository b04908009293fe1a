#include "perception/tracking/contour_model_file.h"

#include <cstring>
#include <filesystem>

#include "core/io/atomic_file.h"
#include "core/io/binary_file.h"
#include "core/io/user_cache.h"

namespace demoplan::perception {

namespace fs = std::filesystem;

namespace {

constexpr char kMagic[8] = {'D', 'P', 'C', 'O', 'N', 'T', 'R', '1'};

std::string file_of(const std::string& folder, std::uint64_t key) {
  char name[32];
  std::snprintf(name, sizeof name, "%016llx.contours", static_cast<unsigned long long>(key));
  return (fs::path(folder) / name).string();
}

}  // namespace

std::uint64_t contour_model_key(const RenderMesh& mesh, const ContourModelOptions& o) {
  std::uint64_t h = hash_bytes(kMagic, sizeof kMagic);
  h = hash_bytes(mesh.vertices.data(), mesh.vertices.size() * sizeof(mesh.vertices[0]), h);
  h = hash_bytes(mesh.triangles.data(), mesh.triangles.size() * sizeof(mesh.triangles[0]), h);
  const int options[3] = {o.views, o.points, o.image_size};
  return hash_bytes(options, sizeof options, h);
}

std::optional<ContourModel> read_contour_model(const std::string& folder, std::uint64_t key) {
  if (folder.empty()) return std::nullopt;
  std::string bytes;
  if (!read_whole_file(file_of(folder, key), bytes)) return std::nullopt;
  ByteReader in{bytes.data(), bytes.data() + bytes.size()};
  char magic[8];
  std::uint64_t stored = 0;
  std::uint32_t views = 0;
  Eigen::Vector3d centre;
  double radius = 0;
  if (!in.get(magic) || std::memcmp(magic, kMagic, sizeof magic) != 0 || !in.get(stored) || stored != key ||
      !in.get(centre) || !in.get(radius) || !in.get(views) || views > 100000)
    return std::nullopt;
  std::vector<ContourView> out(views);
  for (auto& v : out) {
    std::uint32_t points = 0;
    if (!in.get(v.direction) || !in.get(points) || points > 100000) return std::nullopt;
    v.points.resize(points);
    for (auto& p : v.points)
      if (!in.get(p.position) || !in.get(p.normal) || !in.get(p.inner) || !in.get(p.outer)) return std::nullopt;
  }
  return ContourModel(std::move(out), centre, radius);
}

void write_contour_model(const std::string& folder, std::uint64_t key, const ContourModel& model) {
  if (folder.empty()) return;
  std::string bytes(kMagic, sizeof kMagic);
  put_bytes(bytes, key);
  put_bytes(bytes, model.centre());
  put_bytes(bytes, model.radius());
  put_bytes(bytes, static_cast<std::uint32_t>(model.views().size()));
  for (const auto& v : model.views()) {
    put_bytes(bytes, v.direction);
    put_bytes(bytes, static_cast<std::uint32_t>(v.points.size()));
    for (const auto& p : v.points) put_bytes(bytes, p.position), put_bytes(bytes, p.normal), put_bytes(bytes, p.inner), put_bytes(bytes, p.outer);
  }
  try {
    std::error_code ec;
    fs::create_directories(folder, ec);
    write_file_atomic(file_of(folder, key), bytes);
  } catch (const std::exception&) {
    // A read-only or full disk: the model is simply built again next time.
  }
}

ContourModel cached_contour_model(const RenderMesh& mesh, const ContourModelOptions& options, const std::string& folder) {
  const std::uint64_t key = contour_model_key(mesh, options);
  if (auto stored = read_contour_model(folder, key)) return std::move(*stored);
  ContourModel model(mesh, options);
  write_contour_model(folder, key, model);
  return model;
}

std::string default_contour_cache_folder() { return user_cache_folder("contours"); }

}  // namespace demoplan::perception
