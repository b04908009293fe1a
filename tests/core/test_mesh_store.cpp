// Meshes kept on disk between runs: read back as parsed, and never once any file the mesh was
// read from (its own, its materials, its texture) has changed, appeared or gone.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>

#include "core/model/mesh.h"
#include "core/model/mesh_store.h"
#include "tests/support/temp_folder.h"

using namespace demoplan;
namespace fs = std::filesystem;

namespace {

const std::string kData = DEMOPLAN_DATA_DIR;

void expect_same(const TriangleMesh& a, const TriangleMesh& b) {
  EXPECT_EQ(a.path, b.path);
  EXPECT_EQ(a.vertices, b.vertices);
  EXPECT_EQ(a.normals, b.normals);
  EXPECT_EQ(a.uvs, b.uvs);
  EXPECT_EQ(a.triangles, b.triangles);
  EXPECT_EQ(a.texture_path, b.texture_path);
  EXPECT_EQ(a.color, b.color);
}

// The folder set for one test, unset after it.
struct StoreFolder {
  explicit StoreFolder(const std::string& folder) { set_mesh_store_folder(folder); }
  ~StoreFolder() { set_mesh_store_folder(""); }
};

// A tetrahedron whose material (red, textured) is in a file of its own.
std::string write_tetrahedron(const test::TempFolder& dir) {
  dir.write("part.mtl", "newmtl red\nKd 0.9 0.1 0.1\nmap_Kd part.png\n");
  return dir.write("part.obj",
                   "mtllib part.mtl\nv 0 0 0\nv 0.1 0 0\nv 0 0.1 0\nv 0 0 0.1\nvt 0 0\nvt 1 0\nvt 0 1\nvt 1 1\n"
                   "usemtl red\nf 1/1 3/3 2/2\nf 1/1 2/2 4/4\nf 1/1 4/4 3/3\nf 2/2 3/3 4/4\n");
}

}  // namespace

TEST(MeshStore, AStoredMeshReadsBackAsParsed) {
  test::TempFolder dir("demoplan_mesh_store");
  const std::string folder = dir.file("store");
  const std::string path = kData + "/objects/ycbv/meshes/obj_000005.obj";
  const auto parsed = load_mesh(path);  // no folder set: parsed, nothing stored
  EXPECT_FALSE(fs::exists(folder));
  EXPECT_EQ(read_stored_mesh(folder, path), nullptr);
  {
    const StoreFolder set(folder);
    expect_same(*load_mesh(path), *parsed);  // parsed and stored
  }
  const auto stored = read_stored_mesh(folder, path);
  ASSERT_NE(stored, nullptr);
  expect_same(*stored, *parsed);
  EXPECT_GT(stored->triangles.size(), 15000u);
  EXPECT_FALSE(stored->texture_path.empty());  // the YCB-V part's texture, beside it
  EXPECT_EQ(read_stored_mesh(folder, path + "x"), nullptr);  // another path
}

TEST(MeshStore, AnyChangedSourceMakesItReadAgain) {
  test::TempFolder dir("demoplan_mesh_store_sources");
  const std::string folder = dir.file("store");
  const std::string path = write_tetrahedron(dir);
  const StoreFolder set(folder);
  const auto first = load_mesh(path);
  EXPECT_EQ(first->triangles.size(), 4u);
  EXPECT_NEAR(first->color.x(), 0.9f, 1e-6);
  EXPECT_TRUE(first->texture_path.empty());  // part.png does not exist (yet)
  ASSERT_NE(read_stored_mesh(folder, path), nullptr);

  // The material changes: the stored mesh is not used, the new colour is read.
  dir.write("part.mtl", "newmtl red\nKd 0.2 0.7 0.1\nmap_Kd part.png\n");
  EXPECT_EQ(read_stored_mesh(folder, path), nullptr);
  EXPECT_NEAR(load_mesh(path)->color.y(), 0.7f, 1e-6);
  ASSERT_NE(read_stored_mesh(folder, path), nullptr);

  // The texture appears.
  dir.write("part.png", "not really a picture");
  EXPECT_EQ(read_stored_mesh(folder, path), nullptr);
  EXPECT_EQ(load_mesh(path)->texture_path, dir.file("part.png"));
  ASSERT_NE(read_stored_mesh(folder, path), nullptr);

  // The mesh file changes (a vertex moved).
  std::string obj;
  {
    std::ifstream in(path);
    obj.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  }
  obj.replace(obj.find("v 0.1 0 0"), 9, "v 0.2 0 0");
  dir.write("part.obj", obj);
  EXPECT_EQ(read_stored_mesh(folder, path), nullptr);
  const auto moved = load_mesh(path);
  float largest_x = 0;
  for (const auto& v : moved->vertices) largest_x = std::max(largest_x, v.x());
  EXPECT_FLOAT_EQ(largest_x, 0.2f);

  // The material file goes: read again (and without its colour).
  fs::remove(dir.file("part.mtl"));
  EXPECT_EQ(read_stored_mesh(folder, path), nullptr);
}

TEST(MeshStore, ADamagedFileIsNotUsed) {
  test::TempFolder dir("demoplan_mesh_store_damaged");
  const std::string folder = dir.file("store");
  const std::string path = write_tetrahedron(dir);
  {
    const StoreFolder set(folder);
    load_mesh(path);
  }
  ASSERT_EQ(std::distance(fs::directory_iterator(folder), fs::directory_iterator()), 1);
  const fs::path file = fs::directory_iterator(folder)->path();
  std::string good;
  {
    std::ifstream in(file, std::ios::binary);
    good.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  }
  for (size_t at : {size_t{2}, size_t{10}, good.size() / 2, good.size() - 1}) {
    std::string bad = good;
    bad[at] = static_cast<char>(bad[at] ^ 0x04);
    std::ofstream(file, std::ios::binary | std::ios::trunc) << bad;
    EXPECT_EQ(read_stored_mesh(folder, path), nullptr) << "byte " << at;
  }
  std::ofstream(file, std::ios::binary | std::ios::trunc) << good.substr(0, good.size() - 3);
  EXPECT_EQ(read_stored_mesh(folder, path), nullptr);
  std::ofstream(file, std::ios::binary | std::ios::trunc) << good;
  EXPECT_NE(read_stored_mesh(folder, path), nullptr);
}
