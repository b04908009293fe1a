// Markers stuck on a part's face by clicking (part_markers.h): frame, ids, and a clear refusal
// where the square would hang over an edge.
#include <gtest/gtest.h>

#include "core/cell/part_markers.h"
#include "core/error.h"
#include "tests/support/box_stl.h"
#include "tests/support/temp_folder.h"

namespace demoplan {
namespace {

struct BoxPart {
  test::TempFolder dir{"demoplan_part_markers"};
  Cell cell;
  std::shared_ptr<const TriangleMesh> mesh;

  BoxPart() {
    test::write_box_stl(dir.file("box.stl"), 100, 60, 40);  // mm
    mesh = load_mesh(dir.file("box.stl"));
    cell.file = dir.file("cell.json");
    CellPart p;
    p.name = "block";
    p.mesh = dir.file("box.stl");
    p.scale = 0.001;
    cell.parts.push_back(p);
  }
};

TEST(PartMarkers, FlatOnTheFaceWithTheTopEdgeAlongThePartsZ) {
  BoxPart b;
  // The +x face (x = 50 mm): z out of it, top edge along +z, 1 mm in front.
  const CellMarker side = marker_on_face(b.cell, 0, *b.mesh, {0.05, 0.0, 0.0}, {1, 0, 0}, 0.03);
  EXPECT_EQ(side.id, 0);
  EXPECT_DOUBLE_EQ(side.size, 0.03);
  EXPECT_TRUE(side.pose.linear().col(2).isApprox(Eigen::Vector3d::UnitX()));
  EXPECT_TRUE(side.pose.linear().col(1).isApprox(Eigen::Vector3d::UnitZ()));
  EXPECT_NEAR(side.pose.linear().determinant(), 1.0, 1e-12);  // not mirrored
  EXPECT_TRUE(side.pose.translation().isApprox(Eigen::Vector3d(0.051, 0, 0)));
  // The top face (z = 20 mm): top edge along +x.
  const CellMarker top = marker_on_face(b.cell, 0, *b.mesh, {0.01, 0.0, 0.02}, {0, 0, 1}, 0.03);
  EXPECT_TRUE(top.pose.linear().col(1).isApprox(Eigen::Vector3d::UnitX()));
  EXPECT_TRUE(top.pose.linear().col(2).isApprox(Eigen::Vector3d::UnitZ()));
}

TEST(PartMarkers, TakeTheSmallestFreeId) {
  BoxPart b;
  for (int id : {0, 1, 3}) b.cell.parts[0].markers.push_back({id, 0.02, Pose::Identity()});
  EXPECT_EQ(free_marker_id(b.cell), 2);
  EXPECT_EQ(marker_on_face(b.cell, 0, *b.mesh, {0, 0.03, 0}, {0, 1, 0}, 0.02).id, 2);
}

TEST(PartMarkers, RefusedWhereTheSquareWouldHangOverAnEdge) {
  BoxPart b;
  // The +x face is 60 x 40 mm: a 30 mm marker 10 mm below its top edge reaches 5 mm beyond it.
  try {
    marker_on_face(b.cell, 0, *b.mesh, {0.05, 0.0, 0.01}, {1, 0, 0}, 0.03);
    FAIL() << "a marker over the edge was accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.field(), "parts[0].markers");
    EXPECT_NE(e.reason().find("block"), std::string::npos) << e.what();
    EXPECT_NE(e.reason().find("does not lie flat"), std::string::npos) << e.what();
  }
  // A 20 mm marker in the face's middle fits; a size of 0 is refused.
  EXPECT_NO_THROW(marker_on_face(b.cell, 0, *b.mesh, {0.05, 0.0, 0.0}, {1, 0, 0}, 0.02));
  EXPECT_THROW(marker_on_face(b.cell, 0, *b.mesh, {0.05, 0.0, 0.0}, {1, 0, 0}, 0.0), InputError);
}

}  // namespace
}  // namespace demoplan
