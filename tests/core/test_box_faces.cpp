// The six faces of a box: each a rectangle on the box's surface, counter-clockwise seen from
// outside (its normal by the right-hand rule points away from the box), one per side.
#include <gtest/gtest.h>

#include <cmath>

#include "core/geometry/box_faces.h"

namespace demoplan {
namespace {

TEST(BoxFaces, SixRectanglesEachCounterClockwiseSeenFromOutside) {
  const Eigen::AlignedBox3d box(Eigen::Vector3d(-0.2, -0.1, 0.0), Eigen::Vector3d(0.4, 0.3, 0.05));
  const auto faces = box_faces(box);
  ASSERT_EQ(faces.size(), 6u);
  std::vector<Eigen::Vector3d> normals;
  for (const auto& f : faces) {
    ASSERT_EQ(f.size(), 4u);
    const Eigen::Vector3d n = (f[1] - f[0]).cross(f[2] - f[1]).normalized();
    Eigen::Vector3d middle = Eigen::Vector3d::Zero();
    for (const auto& v : f) {
      EXPECT_LT(box.exteriorDistance(v), 1e-12);  // on the box
      EXPECT_NEAR((v - f[0]).dot(n), 0.0, 1e-12);  // flat
      middle += v / 4;
    }
    // Its normal is a box axis, pointing from the box's centre through the face.
    EXPECT_NEAR(n.cwiseAbs().maxCoeff(), 1.0, 1e-12);
    EXPECT_GT(n.dot(middle - box.center()), 0.0);
    // Convex: every corner turns the same way.
    for (size_t i = 0; i < 4; ++i) EXPECT_GT((f[(i + 1) % 4] - f[i]).cross(f[(i + 2) % 4] - f[(i + 1) % 4]).dot(n), 0.0);
    normals.push_back(n);
  }
  // One face per side.
  for (size_t i = 0; i < normals.size(); ++i)
    for (size_t j = i + 1; j < normals.size(); ++j) EXPECT_LT(normals[i].dot(normals[j]), 0.5);
}

TEST(BoxFaces, AFlatBoxHasItsTopAndBottomOnly) {
  const auto faces = box_faces(Eigen::AlignedBox3d(Eigen::Vector3d(-0.2, -0.15, 0.0), Eigen::Vector3d(0.2, 0.15, 0.0)));
  ASSERT_EQ(faces.size(), 2u);
  for (const auto& f : faces) {
    const Eigen::Vector3d n = (f[1] - f[0]).cross(f[2] - f[1]);
    EXPECT_NEAR(std::abs(n.normalized().z()), 1.0, 1e-12);
  }
  EXPECT_LT(((faces[0][1] - faces[0][0]).cross(faces[0][2] - faces[0][1])).z() *
                ((faces[1][1] - faces[1][0]).cross(faces[1][2] - faces[1][1])).z(),
            0.0);  // one looks up, the other down
}

}  // namespace
}  // namespace demoplan
