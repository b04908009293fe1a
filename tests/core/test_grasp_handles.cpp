// Grasp handles generated from a mesh: each closes on two faces that face each other within the
// opening, with the open hand out of the part; a part too wide has none and says why; on the
// benchmark's YCB-V parts they come close to the hand-made SRDF handles.
#include <cmath>

#include <gtest/gtest.h>

#include "core/demo/benchmark_scene.h"
#include "core/model/srdf.h"
#include "core/part/grasp_handles.h"
#include "core/part/mesh_lines.h"
#include "core/part/resting_placements.h"

namespace demoplan {
namespace {

const std::string kData = DEMOPLAN_DATA_DIR;

TriangleMesh box_mesh(const Eigen::Vector3d& size) {
  TriangleMesh m;
  m.path = "box";
  for (int i = 0; i < 8; ++i)
    m.vertices.emplace_back((i & 1 ? 0.5f : -0.5f) * size.x(), (i & 2 ? 0.5f : -0.5f) * size.y(), (i & 4 ? 0.5f : -0.5f) * size.z());
  const std::uint32_t faces[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (const auto& f : faces) m.triangles.push_back({f[0], f[1], f[2]}), m.triangles.push_back({f[0], f[2], f[3]});
  return m;
}

ParallelGripper panda_gripper() {
  const BenchmarkRobot panda = load_benchmark_robot(kData, "panda");
  return parallel_gripper(load_urdf(panda.urdf), load_srdf(panda.srdf));
}

TEST(ParallelGripper, PandaHandOpensEightCentimetres) {
  const ParallelGripper g = panda_gripper();
  EXPECT_DOUBLE_EQ(g.opening, 0.08);
  EXPECT_GE(g.hand.size(), 3u);  // hand and two fingers
}

TEST(GraspHandles, ABoxIsGraspedAcrossItsNarrowSidesWithTheHandOutside) {
  const TriangleMesh box = box_mesh({0.05, 0.06, 0.2});
  const ParallelGripper gripper = panda_gripper();
  const GraspReport r = generate_handles(box, 1.0, Eigen::Vector3d::Zero(), gripper);
  ASSERT_GE(r.handles.size(), 4u);
  EXPECT_TRUE(r.why_none.empty());
  std::vector<Eigen::Vector3d> vertices;
  for (const auto& v : box.vertices) vertices.push_back(v.cast<double>());
  for (const auto& h : r.handles) {
    SCOPED_TRACE(h.frame.name);
    EXPECT_GE(h.quality, 0.0);
    EXPECT_LE(h.quality, 1.0);
    // Closing across the 5 or 6 cm sides (the 20 cm one does not fit the 8 cm opening).
    const Eigen::Vector3d z = h.frame.pose.linear().col(2);
    const double width = std::abs(z.x()) > 0.99 ? 0.05 : std::abs(z.y()) > 0.99 ? 0.06 : -1.0;
    EXPECT_NEAR(h.width, width, 1e-6);
    EXPECT_LE(h.frame.clearance, gripper.opening);
    EXPECT_GE(h.frame.clearance, h.width);
    // The closing line through the handle meets the part at exactly two faces, h.width apart.
    const MeshLines lines(vertices, box.triangles, z);
    const auto hits = lines.cross(h.frame.pose.translation());
    ASSERT_EQ(hits.size(), 2u);
    EXPECT_NEAR(hits[1].t - hits[0].t, h.width, 1e-9);
    EXPECT_NEAR(hits[0].t + hits[1].t, 0.0, 1e-9);  // the handle is midway
  }
  // The best grasps hold the box at its centre of mass's height, across the 5 cm side, from
  // its top as deep as the palm allows: the palm stays clear by the palm clearance.
  EXPECT_LT(r.handles[0].frame.pose.translation().head<2>().norm(), 1e-6);
}

// A part drawn turned in its mesh frame (YCB-V's mustard bottle is, by 27 degrees) is approached
// along its own sides, not along the frame's axes, when it is closed across its height.
TEST(GraspHandles, APartTurnedInItsMeshFrameIsApproachedAlongItsOwnSides) {
  TriangleMesh box = box_mesh({0.12, 0.03, 0.05});
  const Eigen::Matrix3f turn = Eigen::AngleAxisf(27.0f * static_cast<float>(M_PI) / 180, Eigen::Vector3f::UnitZ()).toRotationMatrix();
  for (auto& v : box.vertices) v = turn * v;
  const Eigen::Vector3d side = turn.col(0).cast<double>();  // the box's long side
  const GraspReport r = generate_handles(box, 1.0, Eigen::Vector3d::Zero(), panda_gripper());
  int across_height = 0;
  for (const auto& h : r.handles) {
    if (std::abs(h.frame.pose.linear().col(2).z()) < 0.99) continue;  // closing across the 5 cm height only
    ++across_height;
    const Eigen::Vector3d approach = h.frame.pose.linear().col(0);
    const double along_side = std::abs(approach.dot(side)), across_side = std::abs(approach.dot(Eigen::Vector3d::UnitZ().cross(side)));
    // Every 45 degrees from the long side: along it, across it or on a diagonal, never 18 degrees off.
    const double off = std::min({std::acos(std::min(1.0, along_side)), std::acos(std::min(1.0, across_side)),
                                 std::abs(std::acos(std::min(1.0, along_side)) - M_PI / 4)});
    EXPECT_LT(off, 2 * M_PI / 180) << h.frame.name << " approach " << approach.transpose();
  }
  EXPECT_GE(across_height, 2);
}

TEST(GraspHandles, APartWiderThanTheOpeningHasNoneAndSaysWhy) {
  const GraspReport r = generate_handles(box_mesh({0.15, 0.12, 0.1}), 1.0, Eigen::Vector3d::Zero(), panda_gripper());
  EXPECT_TRUE(r.handles.empty());
  EXPECT_NE(r.why_none.find("too wide"), std::string::npos) << r.why_none;
  EXPECT_NE(r.why_none.find("100 mm"), std::string::npos) << r.why_none;
}

// For every YCB-V part of the benchmark: the share of its SRDF handles with a generated handle
// within 1 cm and 15 degrees.
TEST(GraspHandles, YcbvPartsGetHandlesCloseToTheHandMadeOnes) {
  const ParallelGripper gripper = panda_gripper();
  int matched = 0, total = 0;
  for (const std::string id : {"02", "03", "04", "05", "07", "08", "09", "12", "21"}) {
    const std::string name = "obj_0000" + id;
    const auto mesh = load_mesh(kData + "/objects/ycbv/meshes/" + name + ".obj");
    const Srdf srdf = load_srdf(kData + "/objects/ycbv/srdf/" + name + ".srdf");
    const GraspReport r = generate_handles(*mesh, 0.001, centre_of_mass(*mesh, 0.001), gripper);
    int part_matched = 0;
    for (const auto& s : srdf.handles) {
      bool found = false;
      for (const auto& g : r.handles) found |= handle_matches(g.frame.pose, s.pose);
      part_matched += found;
    }
    std::printf("%s: %d of %zu SRDF handles matched by %zu generated (%.0f ms)\n", name.c_str(), part_matched,
                srdf.handles.size(), r.handles.size(), r.seconds * 1000);
    matched += part_matched;
    total += static_cast<int>(srdf.handles.size());
  }
  std::printf("all parts: %d of %d\n", matched, total);
  // Measured 56 of 76 (2026-12-03; 36 with the deepest grasp only and the mesh frame's axes,
  // 41 with the part's own long side). The misses are hand-made choices no rule of ours makes:
  // rim grasps at 45 degrees (obj_000002/3), closing directions we rank below the 48 we keep
  // (obj_000021's 24 handles close in three directions), a grasp 3 cm off the centre (obj_000012).
  EXPECT_GE(matched, 54);
}

}  // namespace
}  // namespace demoplan
