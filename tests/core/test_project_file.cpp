// The project file: the parts the operator placed again for the part-model tracker are written and
// read back, and a wrong one is named by its field.
#include <functional>

#include <gtest/gtest.h>

#include "core/error.h"
#include "core/project/project.h"

namespace demoplan {
namespace {

Project two_parts() {
  Project p;
  p.demonstration.object_ids = {"YCBV_02", "YCBV_03"};
  return p;
}

TEST(ProjectFile, ThePartsPlacedAgainAreReadBack) {
  Project p = two_parts();
  Pose placed = Pose::Identity();
  placed.linear() = Eigen::AngleAxisd(0.7, Eigen::Vector3d(0.2, 0.3, 1.0).normalized()).toRotationMatrix();
  placed.translation() = Eigen::Vector3d(0.41, -0.12, 0.83);
  p.tracker_corrections = {{"YCBV_03", 92, placed}, {"YCBV_02", 40, Pose::Identity()}};
  const Project back = project_from_json(project_to_json(p, "/tmp/p.demoplan"), "/tmp/p.demoplan");
  ASSERT_EQ(back.tracker_corrections.size(), 2u);
  EXPECT_EQ(back.tracker_corrections[0].id, "YCBV_03");
  EXPECT_EQ(back.tracker_corrections[0].frame, 92);
  EXPECT_LT((back.tracker_corrections[0].world_T_object.matrix() - placed.matrix()).cwiseAbs().maxCoeff(), 1e-12);
  EXPECT_EQ(back.tracker_corrections[1].id, "YCBV_02");
  EXPECT_EQ(back.tracker_corrections[1].frame, 40);
  // None placed: no key, and a file without it reads as none.
  const Json none = project_to_json(two_parts(), "/tmp/p.demoplan");
  EXPECT_FALSE(none.contains("tracker_corrections"));
  EXPECT_TRUE(project_from_json(none, "/tmp/p.demoplan").tracker_corrections.empty());
}

TEST(ProjectFile, AWrongPlacementIsNamedByItsField) {
  Project p = two_parts();
  p.tracker_corrections = {{"YCBV_03", 92, Pose::Identity()}};
  const Json good = project_to_json(p, "/tmp/p.demoplan");
  auto refused = [&](const std::function<void(Json&)>& spoil, const std::string& field, const std::string& words) {
    Json j = good;
    spoil(j);
    try {
      project_from_json(j, "/tmp/p.demoplan");
      ADD_FAILURE() << "accepted; expected an error in " << field;
    } catch (const InputError& e) {
      EXPECT_EQ(e.field(), field) << e.what();
      EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("/tmp/p.demoplan"), std::string::npos) << e.what();
    }
  };
  refused([](Json& j) { j["tracker_corrections"][0]["id"] = "YCBV_99"; }, "tracker_corrections[0].id",
          "not in the demonstration");
  refused([](Json& j) { j["tracker_corrections"][0]["frame"] = 0; }, "tracker_corrections[0].frame", "after the start");
  refused([](Json& j) { j["tracker_corrections"].push_back(j["tracker_corrections"][0]); },
          "tracker_corrections[1].frame", "placed twice in frame 92");
  refused([](Json& j) { j["tracker_corrections"][0]["world_T_object"][0][0] = 2.0; },
          "tracker_corrections[0].world_T_object", "orthonormal");
}

}  // namespace
}  // namespace demoplan
