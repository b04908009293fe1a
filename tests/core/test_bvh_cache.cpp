// Mesh BVHs are fitted once per process and shared by every checker and validator.
#include <gtest/gtest.h>

#include <random>
#include <thread>

#include "core/demo/benchmark_scene.h"
#include "core/scene/bvh_cache.h"
#include "core/scene/collision_checker.h"
#include "core/validation/path_validator.h"

using namespace demoplan;

static const std::string kData = DEMOPLAN_DATA_DIR;

namespace {

const TriangleMesh* first_robot_mesh(const Scene& scene) {
  for (const auto& link : scene.robot.model.links)
    for (const auto& g : link.collisions)
      if (auto* m = std::get_if<MeshShape>(&g.shape)) return m->mesh.get();
  return nullptr;
}

Eigen::VectorXd random_q(const Scene& scene, std::mt19937_64& rng) {
  const auto& model = scene.robot.model;
  const Eigen::VectorXd lo = model.lower_limits(), hi = model.upper_limits();
  std::uniform_real_distribution<double> u(0, 1);
  Eigen::VectorXd q(model.nq);
  for (int i = 0; i < model.nq; ++i) q[i] = lo[i] + u(rng) * (hi[i] - lo[i]);
  return q;
}

std::vector<std::pair<std::string, std::string>> names(const std::vector<CollisionPair>& pairs) {
  std::vector<std::pair<std::string, std::string>> out;
  for (const auto& p : pairs) out.emplace_back(p.first, p.second);
  return out;
}

}  // namespace

TEST(BvhCache, SceneLoadedTwiceIsNotFittedAgain) {
  const BenchmarkTask task1 = load_benchmark_task(kData, "shelf_2");
  const Scene scene1 = build_benchmark_scene(task1, "panda", 0);
  const CollisionChecker checker1(scene1);
  const std::size_t fits = bvh_fits();
  ASSERT_GT(fits, 0u);  // the Panda's links and the shelf are meshes

  // From disk again, without a MeshCache: new TriangleMesh objects, same files.
  const BenchmarkTask task2 = load_benchmark_task(kData, "shelf_2");
  const Scene scene2 = build_benchmark_scene(task2, "panda", 0);
  ASSERT_NE(first_robot_mesh(scene1), nullptr);
  ASSERT_NE(first_robot_mesh(scene1), first_robot_mesh(scene2));
  const CollisionChecker checker2(scene2);
  EXPECT_EQ(bvh_fits(), fits);

  // The validator builds a checker of its own; a path standing still at the start.
  const SceneState start = benchmark_start_state(task2, scene2);
  ValidationTask vt;
  vt.q_initial = scene2.robot.initial_configuration;
  vt.start_objects = vt.goal_objects = start.objects;
  vt.source = "test";
  Path path;
  Waypoint w;
  w.q = vt.q_initial;
  w.objects = start.objects;
  path.waypoints = {w, w};
  const ValidationReport report = validate_path(scene2, vt, path);
  EXPECT_TRUE(report.valid) << report.message;
  EXPECT_EQ(bvh_fits(), fits);

  // Both checkers answer alike, on free and colliding configurations.
  auto d1 = checker1.make_data();
  auto d2 = checker2.make_data();
  std::mt19937_64 rng(11);
  int colliding = 0, free = 0;
  for (int i = 0; i < 300; ++i) {
    SceneState s = benchmark_start_state(task1, scene1);
    s.q = random_q(scene1, rng);
    const auto pairs1 = checker1.collisions(s, d1);
    const auto pairs2 = checker2.collisions(s, d2);
    ASSERT_EQ(names(pairs1), names(pairs2)) << "configuration " << i;
    const bool hit = checker1.in_collision(s, d1);
    ASSERT_EQ(hit, checker2.in_collision(s, d2)) << "configuration " << i;
    ASSERT_EQ(hit, !pairs1.empty());
    (hit ? colliding : free) += 1;
    if (i % 30 == 0) {
      EXPECT_EQ(checker1.distance(s, d1).distance, checker2.distance(s, d2).distance);
    }
  }
  EXPECT_GT(colliding, 0);
  EXPECT_GT(free, 0);
}

TEST(BvhCache, MeshWithoutPathIsFittedOncePerScaleAcrossThreads) {
  // A tetrahedron no file holds, so no other test has fitted it.
  TriangleMesh mesh;
  mesh.vertices = {{0.0f, 0.0f, 0.0f}, {0.31f, 0.0f, 0.0f}, {0.0f, 0.37f, 0.0f}, {0.0f, 0.0f, 0.41f}};
  mesh.triangles = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
  const std::size_t before = bvh_fits();

  std::vector<std::shared_ptr<const fcl::CollisionObject<double>>> got(4);
  std::vector<std::thread> threads;
  for (size_t t = 0; t < got.size(); ++t)
    threads.emplace_back([&, t] { got[t] = shared_mesh_bvh(mesh, Eigen::Vector3d::Ones()); });
  for (auto& t : threads) t.join();
  ASSERT_NE(got[0], nullptr);
  for (const auto& g : got) EXPECT_EQ(g, got[0]);
  EXPECT_EQ(bvh_fits(), before + 1);

  const TriangleMesh copy = mesh;  // another object, same content
  EXPECT_EQ(shared_mesh_bvh(copy, Eigen::Vector3d::Ones()), got[0]);
  EXPECT_EQ(bvh_fits(), before + 1);

  const auto scaled = shared_mesh_bvh(mesh, Eigen::Vector3d(2.0, 1.0, 1.0));
  EXPECT_NE(scaled, got[0]);
  EXPECT_EQ(bvh_fits(), before + 2);
}

TEST(BvhCache, SharedMeshesAnswerInInputOrderAndFitOnlyWhatIsMissing) {
  // Three tetrahedra no file holds, of different sizes (the fit order is by size, the answer's by input).
  auto tetrahedron = [](float s) {
    TriangleMesh m;
    m.vertices = {{0.0f, 0.0f, 0.0f}, {0.29f * s, 0.0f, 0.0f}, {0.0f, 0.33f * s, 0.0f}, {0.0f, 0.0f, 0.43f * s}};
    m.triangles = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
    return m;
  };
  const TriangleMesh a = tetrahedron(1.0f), b = tetrahedron(1.7f);
  TriangleMesh c = tetrahedron(0.6f);
  c.triangles.push_back({1, 2, 3});  // more triangles: fitted first
  const Eigen::Vector3d one = Eigen::Vector3d::Ones(), wide(3.0, 1.0, 1.0);
  const std::size_t before = bvh_fits();

  const std::vector<std::pair<const TriangleMesh*, Eigen::Vector3d>> meshes = {
      {&a, one}, {&b, one}, {&c, one}, {&a, wide}, {&a, one}};
  const std::vector<SharedMesh> got = shared_meshes(meshes, 2);
  ASSERT_EQ(got.size(), meshes.size());
  EXPECT_EQ(bvh_fits(), before + 4);  // the repeated (a, one) is fitted once
  for (size_t i = 0; i < meshes.size(); ++i) {
    const SharedMesh alone = shared_mesh(*meshes[i].first, meshes[i].second);
    EXPECT_EQ(got[i].bvh, alone.bvh) << "mesh " << i;
    EXPECT_EQ(got[i].spheres, alone.spheres) << "mesh " << i;
  }
  EXPECT_EQ(got[0].bvh, got[4].bvh);
  EXPECT_NE(got[0].bvh, got[3].bvh);
  EXPECT_NE(got[0].bvh, got[1].bvh);

  const std::vector<SharedMesh> again = shared_meshes(meshes, 2);
  EXPECT_EQ(bvh_fits(), before + 4);
  for (size_t i = 0; i < meshes.size(); ++i) EXPECT_EQ(again[i].bvh, got[i].bvh) << "mesh " << i;
}
