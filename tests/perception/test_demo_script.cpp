// The motion of a synthetic demonstration built from its events (a cell's picks): parts rest at
// the event poses, a carried part leaves its grasp pose, lifts, and lands at its release pose;
// the truth read back from the script has the same events; events that do not pair up are
// refused.
#include <gtest/gtest.h>

#include "core/error.h"
#include "perception/synthetic/demo_script.h"

namespace {

using namespace demoplan;
using namespace demoplan::perception;

Pose at(double x, double y, double z) {
  Pose p = Pose::Identity();
  p.translation() << x, y, z;
  return p;
}

// Part "a" carried from (0, 0, 0.8) to (0.4, 0.2, 0.8) between frames 10 and 30; "b" stays.
Demonstration one_carry() {
  Demonstration d;
  d.task = "test cell";
  d.object_ids = {"a", "b"};
  const PoseList before{at(0, 0, 0.8), at(0.3, -0.3, 0.8)}, after{at(0.4, 0.2, 0.8), at(0.3, -0.3, 0.8)};
  d.events.push_back({10, 0, EventType::Grasp, 1.0, before, {}});
  d.events.push_back({30, 0, EventType::Release, 1.0, after, {}});
  return d;
}

const std::vector<Eigen::AlignedBox3d> kBounds(2, Eigen::AlignedBox3d(Eigen::Vector3d::Constant(-0.03), Eigen::Vector3d::Constant(0.03)));

TEST(DemoScriptFromEvents, PartsRestAtTheEventPosesAndAreCarriedLiftedInBetween) {
  const Demonstration d = one_carry();
  const DemoScript s = make_demo_script(d, d.events[0].poses, kBounds, 12);
  ASSERT_EQ(s.frames, 42);
  ASSERT_EQ(s.carries.size(), 1u);
  EXPECT_EQ(s.carries[0].grasp, 10);
  EXPECT_EQ(s.carries[0].release, 30);
  for (int f = 0; f <= 10; ++f) EXPECT_TRUE(s.poses[f][0].isApprox(at(0, 0, 0.8))) << f;
  for (int f = 30; f < s.frames; ++f) EXPECT_TRUE(s.poses[f][0].isApprox(at(0.4, 0.2, 0.8))) << f;
  EXPECT_GT(s.poses[20][0].translation().z(), 0.85);  // lifted half way
  for (int f = 0; f < s.frames; ++f) EXPECT_TRUE(s.poses[f][1].isApprox(at(0.3, -0.3, 0.8))) << f;

  const Demonstration t = s.truth();
  ASSERT_EQ(t.events.size(), 2u);
  EXPECT_EQ(t.events[0].frame, 10);
  EXPECT_EQ(t.events[1].frame, 30);
  EXPECT_TRUE(t.events[1].poses[0].isApprox(at(0.4, 0.2, 0.8)));
}

TEST(DemoScriptFromEvents, AReleaseWithoutItsGraspIsRefused) {
  Demonstration d = one_carry();
  d.events.erase(d.events.begin());
  EXPECT_THROW(make_demo_script(d, one_carry().events[0].poses, kBounds), InputError);
}

TEST(DemoScriptFromEvents, AGraspNeverReleasedIsRefused) {
  Demonstration d = one_carry();
  d.events.pop_back();
  EXPECT_THROW(make_demo_script(d, d.events[0].poses, kBounds), InputError);
}

}  // namespace
