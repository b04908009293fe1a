// The model tracker started from a pose estimator's BOP results: the first frame with an estimate
// of every part, each part's best estimate there, in the world; clear errors otherwise.
#include <gtest/gtest.h>

#include <string>

#include "core/error.h"
#include "perception/tracking/tracker_init_bop.h"

using namespace demoplan;
using namespace demoplan::perception;

namespace {

BopDetection estimate(int frame, int model, double score, double x) {
  BopDetection d;
  d.image_id = frame, d.object_id = model, d.score = score;
  d.camera_T_object.translation() = Eigen::Vector3d(x, 0.0, 2.0);
  return d;
}

TEST(TrackerInitBop, StartsAtTheFirstFrameWithEveryPartFromItsBestEstimate) {
  Pose world_T_camera = Pose::Identity();
  world_T_camera.linear() = Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitX()).toRotationMatrix();
  world_T_camera.translation() = Eigen::Vector3d(1.0, 2.0, 3.0);
  // Frame 0 shows only the cracker box; frame 1 both, the mustard twice.
  const std::vector<BopDetection> detections{estimate(0, 2, 0.9, 0.0), estimate(1, 5, 0.4, 0.3), estimate(1, 2, 0.8, 0.1),
                                             estimate(1, 5, 0.7, 0.2), estimate(2, 2, 1.0, 0.5), estimate(2, 5, 1.0, 0.5)};
  const TrackerInit init = tracker_init_from_bop(detections, {"YCBV_02", "YCBV_05"}, world_T_camera, "bop.csv");
  EXPECT_EQ(init.frame, 1);
  ASSERT_EQ(init.parts.size(), 2u);
  EXPECT_EQ(init.parts[0].id, "YCBV_02");
  EXPECT_TRUE(init.parts[0].world_T_object.isApprox(world_T_camera * detections[2].camera_T_object));
  EXPECT_EQ(init.parts[1].id, "YCBV_05");
  EXPECT_TRUE(init.parts[1].world_T_object.isApprox(world_T_camera * detections[3].camera_T_object))
      << "the better of the mustard's two estimates";
  EXPECT_TRUE(init.corrections.empty());
}

std::string error_of(const std::vector<BopDetection>& detections, const std::vector<std::string>& parts) {
  try {
    tracker_init_from_bop(detections, parts, Pose::Identity(), "bop.csv");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(TrackerInitBop, NamesThePartsNoFrameHasAndThePartsNoEstimatorKnows) {
  const std::vector<BopDetection> detections{estimate(0, 2, 0.9, 0.0), estimate(3, 2, 0.9, 0.0), estimate(3, 12, 0.9, 0.0)};
  const std::string missing = error_of(detections, {"YCBV_02", "YCBV_05", "YCBV_12"});
  EXPECT_NE(missing.find("bop.csv"), std::string::npos) << missing;
  EXPECT_NE(missing.find("im_id 3"), std::string::npos) << missing;
  EXPECT_NE(missing.find("2 of 3"), std::string::npos) << missing;
  EXPECT_NE(missing.find("'YCBV_05'"), std::string::npos) << missing;
  const std::string tray = error_of(detections, {"YCBV_02", "TRAY"});
  EXPECT_NE(tray.find("'TRAY' is no BOP model"), std::string::npos) << tray;
  const std::string none = error_of({}, {"YCBV_02"});
  EXPECT_NE(none.find("no estimate of any of the parts"), std::string::npos) << none;
}

}  // namespace
