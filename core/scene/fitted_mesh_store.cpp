#include "core/scene/fitted_mesh_store.h"

#include <fcl/config.h>
#include <fcl/geometry/bvh/detail/BV_fitter.h>

#include <cstring>
#include <filesystem>
#include <stdexcept>

#include "core/io/atomic_file.h"
#include "core/io/binary_file.h"
#include "core/io/user_cache.h"

namespace demoplan {

namespace fs = std::filesystem;

namespace {

using Tree = fcl::BVHModel<fcl::OBBRSSd>;
using Fitter = fcl::detail::BVFitterBase<fcl::OBBRSSd>;

// Version 1: the tree's recorded fit, then the sphere set. Raise it when either changes, or when
// the sphere fit (bounding_spheres.cpp) changes what it computes.
constexpr char kMagic[8] = {'D', 'P', 'F', 'I', 'T', 'M', 'S', 'H'};
constexpr std::uint32_t kVersion = 1;
constexpr char kFclVersion[16] = FCL_VERSION;

// FCL's own fitter, each answer kept.
class RecordingFitter final : public Fitter {
public:
  explicit RecordingFitter(RecordedFit& out) : out_(out) {}
  void set(fcl::Vector3d* v, fcl::Triangle* t, fcl::BVHModelType type) override { inner_.set(v, t, type); }
  void set(fcl::Vector3d* v, fcl::Vector3d* prev, fcl::Triangle* t, fcl::BVHModelType type) override {
    inner_.set(v, prev, t, type);
  }
  fcl::OBBRSSd fit(unsigned int* primitives, int count) override {
    const fcl::OBBRSSd bv = inner_.fit(primitives, count);
    out_.counts.push_back(count);
    out_.volumes.push_back(bv);
    return bv;
  }
  void clear() override { inner_.clear(); }

private:
  fcl::detail::BVFitter<fcl::OBBRSSd> inner_;
  RecordedFit& out_;
};

struct ReplayMismatch : std::runtime_error {
  ReplayMismatch() : std::runtime_error("recorded fit does not match the mesh") {}
};

// The recorded answers, in order; refuses a node whose triangle count differs.
class ReplayFitter final : public Fitter {
public:
  explicit ReplayFitter(const RecordedFit& in) : in_(in) {}
  void set(fcl::Vector3d*, fcl::Triangle*, fcl::BVHModelType) override {}
  void set(fcl::Vector3d*, fcl::Vector3d*, fcl::Triangle*, fcl::BVHModelType) override {}
  fcl::OBBRSSd fit(unsigned int*, int count) override {
    if (next_ >= in_.counts.size() || in_.counts[next_] != count) throw ReplayMismatch();
    return in_.volumes[next_++];
  }
  void clear() override {}
  bool used_all() const { return next_ == in_.counts.size(); }

private:
  const RecordedFit& in_;
  size_t next_ = 0;
};

void put_sphere(std::string& out, const BoundingSphere& s) {
  put_bytes(out, s.centre);
  put_bytes(out, s.radius);
}

template <typename T, typename PutOne>
void put_list(std::string& out, const std::vector<T>& list, PutOne put_one) {
  put_bytes(out, static_cast<std::uint64_t>(list.size()));
  for (const auto& x : list) put_one(out, x);
}

// ByteReader with the lists of a sphere set: each item read by `get_one`.
struct Reader : ByteReader {
  bool get_sphere(BoundingSphere& s) { return get(s.centre) && get(s.radius); }
  template <typename T, typename GetOne>
  bool get_list(std::vector<T>& list, size_t item_bytes, GetOne get_one) {
    std::uint64_t n = 0;
    if (!get(n) || n > left() / item_bytes) return false;
    list.resize(n);
    for (auto& x : list)
      if (!get_one(*this, x)) return false;
    return true;
  }
};

std::string file_of(const std::string& folder, const MeshKey& key) {
  char name[48];
  std::snprintf(name, sizeof name, "%016llx%016llx.fit", static_cast<unsigned long long>(key.hash_a),
                static_cast<unsigned long long>(key.hash_b));
  return (fs::path(folder) / name).string();
}

std::string payload_of(const FittedMesh& m) {
  std::string p;
  put_bytes(p, static_cast<std::uint64_t>(m.tree.counts.size()));
  for (size_t i = 0; i < m.tree.counts.size(); ++i) {
    const fcl::OBBRSSd& bv = m.tree.volumes[i];
    put_bytes(p, static_cast<std::int32_t>(m.tree.counts[i]));
    put_bytes(p, bv.obb.axis), put_bytes(p, bv.obb.To), put_bytes(p, bv.obb.extent);
    put_bytes(p, bv.rss.axis), put_bytes(p, bv.rss.To), put_bytes(p, bv.rss.l), put_bytes(p, bv.rss.r);
  }
  const SphereSet& s = m.spheres;
  put_sphere(p, s.all);
  put_list(p, s.parts, put_sphere);
  put_list(p, s.children, put_sphere);
  put_list(p, s.children_begin, [](std::string& o, int v) { put_bytes(o, static_cast<std::int32_t>(v)); });
  put_list(p, s.witnesses, [](std::string& o, const Eigen::Vector3d& v) { put_bytes(o, v); });
  put_list(p, s.edges, [](std::string& o, const std::array<Eigen::Vector3d, 2>& e) { put_bytes(o, e[0]), put_bytes(o, e[1]); });
  return p;
}

bool parse_payload(Reader r, FittedMesh& m) {
  std::uint64_t nodes = 0;
  constexpr size_t kNodeBytes = sizeof(std::int32_t) + 30 * sizeof(double);
  if (!r.get(nodes) || nodes > r.left() / kNodeBytes) return false;
  m.tree.counts.resize(nodes);
  m.tree.volumes.resize(nodes);
  for (size_t i = 0; i < nodes; ++i) {
    fcl::OBBRSSd& bv = m.tree.volumes[i];
    std::int32_t count = 0;
    if (!r.get(count) || !r.get(bv.obb.axis) || !r.get(bv.obb.To) || !r.get(bv.obb.extent) || !r.get(bv.rss.axis) ||
        !r.get(bv.rss.To) || !r.get(bv.rss.l) || !r.get(bv.rss.r))
      return false;
    m.tree.counts[i] = count;
  }
  SphereSet& s = m.spheres;
  auto sphere = [](Reader& rd, BoundingSphere& b) { return rd.get_sphere(b); };
  auto index = [](Reader& rd, int& v) {
    std::int32_t x = 0;
    if (!rd.get(x)) return false;
    v = x;
    return true;
  };
  auto point = [](Reader& rd, Eigen::Vector3d& v) { return rd.get(v); };
  auto edge = [](Reader& rd, std::array<Eigen::Vector3d, 2>& e) { return rd.get(e[0]) && rd.get(e[1]); };
  if (!r.get_sphere(s.all) || !r.get_list(s.parts, 32, sphere) || !r.get_list(s.children, 32, sphere) ||
      !r.get_list(s.children_begin, 4, index) || !r.get_list(s.witnesses, 24, point) || !r.get_list(s.edges, 48, edge))
    return false;
  // The sphere set's own shape: every part's children are a range of the children.
  if (!s.parts.empty() && s.children_begin.size() != s.parts.size() + 1) return false;
  for (size_t i = 0; i + 1 < s.children_begin.size(); ++i)
    if (s.children_begin[i] < 0 || s.children_begin[i] > s.children_begin[i + 1]) return false;
  if (!s.children_begin.empty() && static_cast<size_t>(s.children_begin.back()) > s.children.size()) return false;
  return r.at == r.end;
}

}  // namespace

MeshKey mesh_key(const std::vector<Eigen::Vector3d>& vertices, const std::vector<std::array<std::uint32_t, 3>>& triangles) {
  MeshKey k;
  k.vertices = vertices.size();
  k.triangles = triangles.size();
  const size_t vb = vertices.size() * sizeof(Eigen::Vector3d), tb = triangles.size() * sizeof(triangles[0]);
  static_assert(sizeof(Eigen::Vector3d) == 3 * sizeof(double));
  k.hash_a = hash_bytes(triangles.data(), tb, hash_bytes(vertices.data(), vb));
  // The second over the same bytes in another order and from another start: independent enough
  // that a file of another mesh answering to both is not a concern.
  k.hash_b = hash_bytes(vertices.data(), vb, hash_bytes(triangles.data(), tb, 0x84222325cbf29ce4ull ^ (k.vertices << 20) ^ k.triangles));
  return k;
}

std::shared_ptr<Tree> build_obbrss_tree(const std::vector<Eigen::Vector3d>& vertices,
                                        const std::vector<std::array<std::uint32_t, 3>>& triangles,
                                        const RecordedFit* replay, RecordedFit* record) {
  auto tree = std::make_shared<Tree>();
  std::vector<fcl::Triangle> tris;
  tris.reserve(triangles.size());
  for (const auto& t : triangles) tris.emplace_back(t[0], t[1], t[2]);
  std::shared_ptr<ReplayFitter> replayer;
  if (replay) {
    if (replay->counts.size() != replay->volumes.size()) return nullptr;
    tree->bv_fitter = replayer = std::make_shared<ReplayFitter>(*replay);
  } else if (record) {
    *record = {};
    tree->bv_fitter = std::make_shared<RecordingFitter>(*record);
  }
  tree->beginModel(static_cast<int>(tris.size()), static_cast<int>(vertices.size()));
  tree->addSubModel(vertices, tris);
  try {
    tree->endModel();
  } catch (const ReplayMismatch&) {
    return nullptr;
  }
  if (replayer && !replayer->used_all()) return nullptr;
  tree->bv_fitter = std::make_shared<fcl::detail::BVFitter<fcl::OBBRSSd>>();  // as FCL's own for any refit
  return tree;
}

std::optional<FittedMesh> read_fitted_mesh(const std::string& folder, const MeshKey& key) {
  if (folder.empty()) return std::nullopt;
  std::string bytes;
  if (!read_whole_file(file_of(folder, key), bytes)) return std::nullopt;
  Reader r{{bytes.data(), bytes.data() + bytes.size()}};
  char magic[8], fcl_version[16];
  std::uint32_t version = 0;
  MeshKey stored;
  std::uint64_t payload_bytes = 0, checksum = 0;
  if (!r.get(magic) || std::memcmp(magic, kMagic, sizeof magic) != 0 || !r.get(version) || version != kVersion ||
      !r.get(fcl_version) || std::memcmp(fcl_version, kFclVersion, sizeof fcl_version) != 0 || !r.get(stored) ||
      std::memcmp(&stored, &key, sizeof key) != 0 || !r.get(payload_bytes) || !r.get(checksum) ||
      payload_bytes != r.left() || hash_bytes(r.at, payload_bytes) != checksum)
    return std::nullopt;
  FittedMesh m;
  if (!parse_payload(r, m)) return std::nullopt;
  return m;
}

void write_fitted_mesh(const std::string& folder, const MeshKey& key, const FittedMesh& mesh) {
  if (folder.empty()) return;
  const std::string payload = payload_of(mesh);
  std::string bytes(kMagic, sizeof kMagic);
  put_bytes(bytes, kVersion);
  put_bytes(bytes, kFclVersion);
  put_bytes(bytes, key);
  put_bytes(bytes, static_cast<std::uint64_t>(payload.size()));
  put_bytes(bytes, hash_bytes(payload.data(), payload.size()));
  bytes += payload;
  try {
    std::error_code ec;
    fs::create_directories(folder, ec);
    write_file_atomic(file_of(folder, key), bytes);
  } catch (const std::exception&) {
    // A read-only or full disk: the mesh is simply fitted again next time.
  }
}

std::string default_fitted_mesh_folder() { return user_cache_folder("meshes"); }

}  // namespace demoplan
