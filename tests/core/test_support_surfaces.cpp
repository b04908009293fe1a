// Supports found on furniture meshes: a box's top whichever way it is turned, and the two strips
// and the floor of a slotted fixture (a top that is not convex).
#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

#include "core/cell/support_surfaces.h"
#include "core/geometry/polygon_2d.h"
#include "core/model/mesh.h"

namespace demoplan {
namespace {

double area_of(const std::vector<Eigen::Vector3d>& poly, const Pose& world_T_mesh) {
  std::vector<Eigen::Vector2d> flat;
  for (const auto& p : poly) flat.push_back((world_T_mesh * p).head<2>());
  return polygon_area(flat);
}

std::vector<Eigen::Vector3d> scaled(const TriangleMesh& m, double s) {
  std::vector<Eigen::Vector3d> out;
  for (const auto& v : m.vertices) out.push_back(v.cast<double>() * s);
  return out;
}

TEST(SupportSurfaces, SlottedFixtureHasTwoStripsAndASlotFloor) {
  const auto mesh = load_mesh(std::string(DEMOPLAN_DATA_DIR) + "/../cells/parts/slotted_fixture.stl");
  const Pose at = pose_from_xyz_rpy({0.5, 0.3, 0.77}, {0, 0, 0.4});
  const auto polys = support_surfaces(scaled(*mesh, 0.001), mesh->triangles, at, {.min_area = 0.005});
  ASSERT_EQ(polys.size(), 3u);
  // Strips 70 x 150 mm on top (z = 0.79), the slot's floor 60 x 150 mm 20 mm lower.
  EXPECT_NEAR(area_of(polys[0], at), 0.0105, 1e-6);
  EXPECT_NEAR(area_of(polys[1], at), 0.0105, 1e-6);
  EXPECT_NEAR(area_of(polys[2], at), 0.009, 1e-6);
  for (int k = 0; k < 2; ++k)
    for (const auto& p : polys[k]) EXPECT_NEAR((at * p).z(), 0.79, 1e-6);
  for (const auto& p : polys[2]) EXPECT_NEAR((at * p).z(), 0.77, 1e-6);
  // Each polygon is convex and counter-clockwise seen from above.
  for (const auto& poly : polys)
    for (size_t i = 0; i < poly.size(); ++i) {
      const Eigen::Vector2d a = (at * poly[i]).head<2>(), b = (at * poly[(i + 1) % poly.size()]).head<2>(),
                            c = (at * poly[(i + 2) % poly.size()]).head<2>();
      EXPECT_GT(cross2(b - a, c - b), 0.0);
    }
  // With the default minimum area (0.01 m^2) the floor is too small to count.
  EXPECT_EQ(support_surfaces(scaled(*mesh, 0.001), mesh->triangles, at).size(), 2u);
}

TEST(SupportSurfaces, AnUpsideDownFixtureOffersOnlyItsFlatBottom) {
  const auto mesh = load_mesh(std::string(DEMOPLAN_DATA_DIR) + "/../cells/parts/slotted_fixture.stl");
  const Pose flipped = pose_from_xyz_rpy({0, 0, 0.02}, {M_PI, 0, 0});
  const auto polys = support_surfaces(scaled(*mesh, 0.001), mesh->triangles, flipped, {.min_area = 0.005});
  ASSERT_EQ(polys.size(), 1u);
  EXPECT_NEAR(area_of(polys[0], flipped), 0.2 * 0.15, 1e-6);
}

}  // namespace
}  // namespace demoplan
