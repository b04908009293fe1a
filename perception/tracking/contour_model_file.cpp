#include "perception/tracking/contour_model_file.h"

#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/io/atomic_file.h"
#include "core/io/user_cache.h"

namespace demoplan::perception {

namespace fs = std::filesystem;

namespace {

constexpr char kMagic[8] = {'D', 'P', 'C', 'O', 'N', 'T', 'R', '1'};
constexpr std::uint64_t kFnvOffset = 14695981039346656037ull, kFnvPrime = 1099511628211ull;

void mix(std::uint64_t& h, const void* data, size_t bytes) {
  const auto* p = static_cast<const unsigned char*>(data);
  for (size_t i = 0; i < bytes; ++i) h = (h ^ p[i]) * kFnvPrime;
}

std::string file_of(const std::string& folder, std::uint64_t key) {
  char name[32];
  std::snprintf(name, sizeof name, "%016llx.contours", static_cast<unsigned long long>(key));
  return (fs::path(folder) / name).string();
}

template <typename T>
void put(std::string& out, const T& value) {
  out.append(reinterpret_cast<const char*>(&value), sizeof value);
}

template <typename T>
bool get(std::istream& in, T& value) {
  return static_cast<bool>(in.read(reinterpret_cast<char*>(&value), sizeof value));
}

}  // namespace

std::uint64_t contour_model_key(const RenderMesh& mesh, const ContourModelOptions& o) {
  std::uint64_t h = kFnvOffset;
  mix(h, kMagic, sizeof kMagic);
  mix(h, mesh.vertices.data(), mesh.vertices.size() * sizeof(mesh.vertices[0]));
  mix(h, mesh.triangles.data(), mesh.triangles.size() * sizeof(mesh.triangles[0]));
  const int options[3] = {o.views, o.points, o.image_size};
  mix(h, options, sizeof options);
  return h;
}

std::optional<ContourModel> read_contour_model(const std::string& folder, std::uint64_t key) {
  if (folder.empty()) return std::nullopt;
  std::ifstream in(file_of(folder, key), std::ios::binary);
  char magic[8];
  std::uint64_t stored = 0;
  std::uint32_t views = 0;
  Eigen::Vector3d centre;
  double radius = 0;
  if (!in.read(magic, sizeof magic) || std::memcmp(magic, kMagic, sizeof magic) != 0 || !get(in, stored) ||
      stored != key || !get(in, centre) || !get(in, radius) || !get(in, views) || views > 100000)
    return std::nullopt;
  std::vector<ContourView> out(views);
  for (auto& v : out) {
    std::uint32_t points = 0;
    if (!get(in, v.direction) || !get(in, points) || points > 100000) return std::nullopt;
    v.points.resize(points);
    for (auto& p : v.points)
      if (!get(in, p.position) || !get(in, p.normal) || !get(in, p.inner) || !get(in, p.outer)) return std::nullopt;
  }
  return ContourModel(std::move(out), centre, radius);
}

void write_contour_model(const std::string& folder, std::uint64_t key, const ContourModel& model) {
  if (folder.empty()) return;
  std::string bytes(kMagic, sizeof kMagic);
  put(bytes, key);
  put(bytes, model.centre());
  put(bytes, model.radius());
  put(bytes, static_cast<std::uint32_t>(model.views().size()));
  for (const auto& v : model.views()) {
    put(bytes, v.direction);
    put(bytes, static_cast<std::uint32_t>(v.points.size()));
    for (const auto& p : v.points) put(bytes, p.position), put(bytes, p.normal), put(bytes, p.inner), put(bytes, p.outer);
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
