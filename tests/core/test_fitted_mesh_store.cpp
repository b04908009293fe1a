// Fitted meshes kept on disk: a tree rebuilt from its recorded fit is FCL's own tree bit for bit,
// and a file that is damaged, of another mesh or of another format is never used.
#include <fcl/narrowphase/collision_object.h>
#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>

#include "core/model/mesh.h"
#include "core/scene/bvh_cache.h"
#include "core/scene/fitted_mesh_store.h"
#include "tests/support/temp_folder.h"

using namespace demoplan;
namespace fs = std::filesystem;

namespace {

const std::string kData = DEMOPLAN_DATA_DIR;

struct Scaled {
  std::vector<Eigen::Vector3d> vertices;
  std::vector<std::array<std::uint32_t, 3>> triangles;
};

Scaled ycbv_part(const std::string& file, double scale) {
  const auto mesh = load_mesh(kData + "/objects/ycbv/meshes/" + file);
  return {scaled_vertices(*mesh, Eigen::Vector3d::Constant(scale)), mesh->triangles};
}

bool same_bytes(const fcl::OBBRSSd& a, const fcl::OBBRSSd& b) {
  return std::memcmp(a.obb.axis.data(), b.obb.axis.data(), 9 * sizeof(double)) == 0 &&
         std::memcmp(a.obb.To.data(), b.obb.To.data(), 3 * sizeof(double)) == 0 &&
         std::memcmp(a.obb.extent.data(), b.obb.extent.data(), 3 * sizeof(double)) == 0 &&
         std::memcmp(a.rss.axis.data(), b.rss.axis.data(), 9 * sizeof(double)) == 0 &&
         std::memcmp(a.rss.To.data(), b.rss.To.data(), 3 * sizeof(double)) == 0 &&
         std::memcmp(a.rss.l, b.rss.l, 2 * sizeof(double)) == 0 && std::memcmp(&a.rss.r, &b.rss.r, sizeof(double)) == 0;
}

// Number of nodes that differ in any byte of their volume or in their links.
int differing_nodes(const fcl::BVHModel<fcl::OBBRSSd>& a, const fcl::BVHModel<fcl::OBBRSSd>& b) {
  if (a.getNumBVs() != b.getNumBVs()) return -1;
  int differ = 0;
  for (int i = 0; i < a.getNumBVs(); ++i) {
    const auto &x = a.getBV(i), &y = b.getBV(i);
    differ += !same_bytes(x.bv, y.bv) || x.first_child != y.first_child || x.first_primitive != y.first_primitive ||
              x.num_primitives != y.num_primitives;
  }
  return differ;
}

bool same_spheres(const SphereSet& a, const SphereSet& b) {
  auto same = [](const BoundingSphere& x, const BoundingSphere& y) { return x.centre == y.centre && x.radius == y.radius; };
  if (!same(a.all, b.all) || a.parts.size() != b.parts.size() || a.children.size() != b.children.size() ||
      a.children_begin != b.children_begin || a.witnesses != b.witnesses || a.edges != b.edges)
    return false;
  for (size_t i = 0; i < a.parts.size(); ++i)
    if (!same(a.parts[i], b.parts[i])) return false;
  for (size_t i = 0; i < a.children.size(); ++i)
    if (!same(a.children[i], b.children[i])) return false;
  return true;
}

std::string read_bytes(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void write_bytes(const fs::path& p, const std::string& bytes) {
  std::ofstream(p, std::ios::binary | std::ios::trunc) << bytes;
}

}  // namespace

TEST(FittedMeshStore, ReplayedFitRebuildsFclsTreeBitForBit) {
  const Scaled part = ycbv_part("obj_000005.obj", 0.001);  // the mustard bottle, 15k triangles
  const auto plain = build_obbrss_tree(part.vertices, part.triangles);
  RecordedFit record;
  const auto recorded = build_obbrss_tree(part.vertices, part.triangles, nullptr, &record);
  ASSERT_NE(plain, nullptr);
  ASSERT_NE(recorded, nullptr);
  EXPECT_EQ(static_cast<int>(record.counts.size()), plain->getNumBVs());  // one answer per node
  EXPECT_EQ(plain->getNumBVs(), 2 * static_cast<int>(part.triangles.size()) - 1);
  EXPECT_EQ(differing_nodes(*plain, *recorded), 0);

  const auto replayed = build_obbrss_tree(part.vertices, part.triangles, &record);
  ASSERT_NE(replayed, nullptr);
  EXPECT_EQ(differing_nodes(*plain, *replayed), 0);

  // Another mesh's record does not fit this one: refused, not built wrong.
  const Scaled other = ycbv_part("obj_000012.obj", 0.001);
  EXPECT_EQ(build_obbrss_tree(other.vertices, other.triangles, &record), nullptr);
  RecordedFit cut = record;
  cut.counts.pop_back();
  cut.volumes.pop_back();
  EXPECT_EQ(build_obbrss_tree(part.vertices, part.triangles, &cut), nullptr);
}

TEST(FittedMeshStore, FileReadsBackWhatWasWrittenAndNothingElse) {
  test::TempFolder dir("demoplan_fitted_meshes");
  const std::string folder = dir.file("meshes");  // made by the first write
  const Scaled part = ycbv_part("obj_000012.obj", 0.001);
  FittedMesh fitted;
  ASSERT_NE(build_obbrss_tree(part.vertices, part.triangles, nullptr, &fitted.tree), nullptr);
  fitted.spheres = fit_bounding_spheres(part.vertices, part.triangles);
  const MeshKey key = mesh_key(part.vertices, part.triangles);
  EXPECT_FALSE(read_fitted_mesh(folder, key).has_value());
  write_fitted_mesh(folder, key, fitted);

  const auto back = read_fitted_mesh(folder, key);
  ASSERT_TRUE(back.has_value());
  ASSERT_EQ(back->tree.counts, fitted.tree.counts);
  for (size_t i = 0; i < fitted.tree.volumes.size(); ++i)
    ASSERT_TRUE(same_bytes(back->tree.volumes[i], fitted.tree.volumes[i])) << "node " << i;
  EXPECT_TRUE(same_spheres(back->spheres, fitted.spheres));

  // The same mesh scaled by another factor is another mesh.
  const Scaled larger = ycbv_part("obj_000012.obj", 0.0011);
  const MeshKey larger_key = mesh_key(larger.vertices, larger.triangles);
  EXPECT_NE(larger_key.hash_a, key.hash_a);
  EXPECT_NE(larger_key.hash_b, key.hash_b);
  EXPECT_FALSE(read_fitted_mesh(folder, larger_key).has_value());

  // One byte changed anywhere, or the file cut short: not used.
  ASSERT_EQ(std::distance(fs::directory_iterator(folder), fs::directory_iterator()), 1);
  const fs::path file = fs::directory_iterator(folder)->path();
  const std::string good = read_bytes(file);
  for (size_t at : {size_t{3}, size_t{12}, size_t{40}, good.size() / 2, good.size() - 1}) {
    std::string bad = good;
    bad[at] = static_cast<char>(bad[at] ^ 0x10);
    write_bytes(file, bad);
    EXPECT_FALSE(read_fitted_mesh(folder, key).has_value()) << "byte " << at << " of " << good.size();
  }
  write_bytes(file, good.substr(0, good.size() - 8));
  EXPECT_FALSE(read_fitted_mesh(folder, key).has_value());
  write_bytes(file, good);
  EXPECT_TRUE(read_fitted_mesh(folder, key).has_value());
}

TEST(FittedMeshStore, TheCacheReadsAStoredMeshInsteadOfFittingIt) {
  test::TempFolder dir("demoplan_fitted_meshes_cache");
  const std::string folder = dir.file("meshes");
  // A mesh this process has not fitted: a YCB-V part at a scale no other test uses.
  const auto mesh = load_mesh(kData + "/objects/ycbv/meshes/obj_000004.obj");
  const Eigen::Vector3d scale(0.00093, 0.00091, 0.00097);
  const Scaled part{scaled_vertices(*mesh, scale), mesh->triangles};
  FittedMesh fitted;
  const auto tree = build_obbrss_tree(part.vertices, part.triangles, nullptr, &fitted.tree);
  fitted.spheres = fit_bounding_spheres(part.vertices, part.triangles);
  write_fitted_mesh(folder, mesh_key(part.vertices, part.triangles), fitted);

  set_fitted_mesh_folder(folder);
  const std::size_t fits = bvh_fits(), reads = bvh_reads();
  const SharedMesh shared = shared_mesh(*mesh, scale);
  set_fitted_mesh_folder("");
  EXPECT_EQ(bvh_fits(), fits);
  EXPECT_EQ(bvh_reads(), reads + 1);
  const auto& read_tree = static_cast<const fcl::BVHModel<fcl::OBBRSSd>&>(*shared.bvh->collisionGeometry());
  EXPECT_EQ(differing_nodes(*tree, read_tree), 0);
  EXPECT_TRUE(same_spheres(*shared.spheres, fitted.spheres));

  // A mesh fitted with the folder set is stored there.
  set_fitted_mesh_folder(folder);
  shared_mesh(*mesh, scale * 1.01);
  set_fitted_mesh_folder("");
  EXPECT_EQ(bvh_fits(), fits + 1);
  EXPECT_EQ(std::distance(fs::directory_iterator(folder), fs::directory_iterator()), 2);
}
