#include "core/scene/bvh_cache.h"

#include <fcl/fcl.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cstdint>
#include <cstring>
#include <exception>
#include <future>
#include <mutex>
#include <optional>
#include <unordered_map>
#include <vector>

#include "core/io/user_cache.h"
#include "core/model/mesh_store.h"
#include "core/parallel_for.h"
#include "core/scene/fitted_mesh_store.h"

namespace demoplan {

namespace {

using Bvh = fcl::BVHModel<fcl::OBBRSSd>;

// What is fitted: the mesh with its scale applied.
struct FitInput {
  std::vector<fcl::Vector3d> vertices;
  std::vector<fcl::Triangle> triangles;
  const std::vector<std::array<std::uint32_t, 3>>* mesh_triangles = nullptr;  // the same, for the spheres
  MeshKey key;  // of the content: the cache's and the folder's
};

FitInput scaled(const TriangleMesh& mesh, const Eigen::Vector3d& scale) {
  FitInput in;
  in.mesh_triangles = &mesh.triangles;
  in.vertices = scaled_vertices(mesh, scale);
  in.triangles.reserve(mesh.triangles.size());
  for (const auto& t : mesh.triangles) in.triangles.emplace_back(t[0], t[1], t[2]);
  in.key = mesh_key(in.vertices, mesh.triangles);
  return in;
}

// Bit for bit, like the hash: the hash only finds candidates, this decides.
bool fitted_from(const fcl::CollisionObjectd& object, const FitInput& in) {
  const auto& bvh = static_cast<const Bvh&>(*object.collisionGeometry());
  if (bvh.num_vertices != static_cast<int>(in.vertices.size()) ||
      bvh.num_tris != static_cast<int>(in.triangles.size()))
    return false;
  static_assert(sizeof(fcl::Vector3d) == 3 * sizeof(double));
  if (!in.vertices.empty() &&
      std::memcmp(bvh.vertices, in.vertices.data(), in.vertices.size() * sizeof(fcl::Vector3d)) != 0)
    return false;
  for (size_t i = 0; i < in.triangles.size(); ++i)
    for (int k = 0; k < 3; ++k)
      if (bvh.tri_indices[i][k] != in.triangles[i][k]) return false;
  return true;
}

std::atomic<std::size_t> fit_count{0}, read_count{0};

CacheFolderSetting fitted_mesh_folder;

// From the folder of fitted meshes when it holds this one, else fitted (and stored there).
SharedMesh fit(const FitInput& in) {
  const std::string folder = fitted_mesh_folder.get();
  std::shared_ptr<Bvh> bvh;
  std::shared_ptr<const SphereSet> spheres;
  if (auto stored = read_fitted_mesh(folder, in.key)) {
    bvh = build_obbrss_tree(in.vertices, *in.mesh_triangles, &stored->tree);
    if (bvh) {
      spheres = std::make_shared<const SphereSet>(std::move(stored->spheres));
      ++read_count;
    }
  }
  if (!bvh) {
    RecordedFit record;
    bvh = build_obbrss_tree(in.vertices, *in.mesh_triangles, nullptr, folder.empty() ? nullptr : &record);
    spheres = std::make_shared<const SphereSet>(fit_bounding_spheres(in.vertices, *in.mesh_triangles));
    ++fit_count;
    write_fitted_mesh(folder, in.key, {std::move(record), *spheres});
  }
  // The constructor computes the geometry's local AABB: here, before any other thread sees it.
  auto object = std::make_shared<const fcl::CollisionObjectd>(bvh);
  return {std::move(object), std::move(spheres)};
}

struct Entry {
  std::shared_future<SharedMesh> object;  // ready once fitted; others wait on it
};

struct Cache {
  std::mutex mutex;
  std::unordered_multimap<std::uint64_t, std::shared_ptr<Entry>> entries;  // by MeshKey::hash_a
};

Cache& cache() {
  static Cache c;
  return c;
}

std::vector<std::shared_ptr<Entry>> entries_of(std::uint64_t hash) {
  Cache& c = cache();
  std::vector<std::shared_ptr<Entry>> candidates;
  std::lock_guard lock(c.mutex);
  auto [begin, end] = c.entries.equal_range(hash);
  for (auto it = begin; it != end; ++it) candidates.push_back(it->second);
  return candidates;
}

// Outside the lock: a candidate may still be fitting in another thread.
std::optional<SharedMesh> fitted_among(const std::vector<std::shared_ptr<Entry>>& candidates, const FitInput& in) {
  for (const auto& e : candidates) {
    SharedMesh o = e->object.get();
    if (fitted_from(*o.bvh, in)) return o;
  }
  return std::nullopt;
}

std::optional<SharedMesh> find_fitted(const FitInput& in) {
  try {
    return fitted_among(entries_of(in.key.hash_a), in);
  } catch (...) {  // a fit of the same hash failed in another thread: fit here, which raises it again
    return std::nullopt;
  }
}

SharedMesh find_or_fit(const FitInput& in) {
  const std::uint64_t hash = in.key.hash_a;
  Cache& c = cache();
  const std::vector<std::shared_ptr<Entry>> candidates = entries_of(hash);
  if (auto hit = fitted_among(candidates, in)) return *hit;

  std::promise<SharedMesh> promise;
  const auto mine = std::make_shared<Entry>(Entry{promise.get_future().share()});
  bool entered_meanwhile = false;
  {
    std::lock_guard lock(c.mutex);
    auto [begin, end] = c.entries.equal_range(hash);
    for (auto it = begin; it != end; ++it)
      entered_meanwhile |= std::find(candidates.begin(), candidates.end(), it->second) == candidates.end();
    if (!entered_meanwhile) c.entries.emplace(hash, mine);
  }
  // Another thread entered this hash since the look-up: it may be this mesh, so wait for it
  // rather than fit twice.
  if (entered_meanwhile) return find_or_fit(in);

  try {
    SharedMesh o = fit(in);
    promise.set_value(o);
    return o;
  } catch (...) {
    {
      std::lock_guard lock(c.mutex);
      auto [begin, end] = c.entries.equal_range(hash);
      for (auto it = begin; it != end; ++it)
        if (it->second == mine) {
          c.entries.erase(it);
          break;
        }
    }
    promise.set_exception(std::current_exception());
    throw;
  }
}

}  // namespace

SharedMesh shared_mesh(const TriangleMesh& mesh, const Eigen::Vector3d& scale) {
  return find_or_fit(scaled(mesh, scale));
}

std::shared_ptr<const fcl::CollisionObjectd> shared_mesh_bvh(const TriangleMesh& mesh,
                                                             const Eigen::Vector3d& scale) {
  return shared_mesh(mesh, scale).bvh;
}

std::vector<SharedMesh> shared_meshes(const std::vector<std::pair<const TriangleMesh*, Eigen::Vector3d>>& meshes,
                                      int threads) {
  std::vector<SharedMesh> out(meshes.size());
  std::vector<FitInput> inputs(meshes.size());
  std::vector<size_t> misses;
  for (size_t i = 0; i < meshes.size(); ++i) {
    inputs[i] = scaled(*meshes[i].first, meshes[i].second);
    if (auto hit = find_fitted(inputs[i])) out[i] = std::move(*hit);
    else misses.push_back(i);
  }
  std::stable_sort(misses.begin(), misses.end(),
                   [&](size_t a, size_t b) { return inputs[a].triangles.size() > inputs[b].triangles.size(); });
  std::vector<std::exception_ptr> errors(meshes.size());
  parallel_for(misses.size(), threads, [&](size_t k) {
    const size_t i = misses[k];
    try {
      out[i] = find_or_fit(inputs[i]);
    } catch (...) {  // never out of a worker thread
      errors[i] = std::current_exception();
    }
  });
  for (const auto& e : errors)
    if (e) std::rethrow_exception(e);
  return out;
}

std::vector<Eigen::Vector3d> scaled_vertices(const TriangleMesh& mesh, const Eigen::Vector3d& scale) {
  std::vector<Eigen::Vector3d> out;
  out.reserve(mesh.vertices.size());
  for (const auto& v : mesh.vertices) out.push_back(v.cast<double>().cwiseProduct(scale));
  return out;
}

std::size_t bvh_fits() { return fit_count.load(); }

std::size_t bvh_reads() { return read_count.load(); }

void set_fitted_mesh_folder(const std::string& folder) { fitted_mesh_folder.set(folder); }

void keep_meshes_between_runs() {
  set_mesh_store_folder(default_mesh_store_folder());
  set_fitted_mesh_folder(default_fitted_mesh_folder());
}

}  // namespace demoplan
