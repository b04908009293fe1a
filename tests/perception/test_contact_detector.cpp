// Grasp/release detection from pose tracks: timing, hysteresis against jitter, occlusion while
// carried, events hidden by the hand, one far marker's steady error, parts riding together on a tray, outliers, and the Demonstration it gives.
#include <gtest/gtest.h>

#include <random>

#include "perception/events/contact_detector.h"
#include "perception/events/demonstration_builder.h"
#include "perception/synthetic/demo_script.h"
#include "perception/events/track_smoothing.h"

using namespace demoplan;
using namespace demoplan::perception;

namespace {

Pose at(double x, double y, double z, double yaw = 0.0) {
  Pose p = Pose::Identity();
  p.linear() = Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  p.translation() << x, y, z;
  return p;
}

// Parts at rest at `rest`, carried between (grasp, release) frames to the next rest.
struct Plan {
  int object;
  int grasp, release;
  Pose to;
};

PoseTracks make_tracks(int frames, const std::vector<Pose, Eigen::aligned_allocator<Pose>>& start,
                       const std::vector<Plan>& plans, double noise = 0.0, unsigned seed = 1) {
  PoseTracks t;
  for (size_t k = 0; k < start.size(); ++k) {
    t.object_ids.push_back("P" + std::to_string(k));
    t.planning.push_back(true);
  }
  t.resize(frames);
  std::mt19937 rng(seed);
  std::normal_distribution<double> n(0.0, 1.0);
  for (size_t k = 0; k < start.size(); ++k) {
    Pose cur = start[k];
    for (int f = 0; f < frames; ++f) {
      Pose p = cur;
      for (const auto& pl : plans)
        if (pl.object == static_cast<int>(k)) {
          if (f > pl.grasp && f < pl.release) p = carry_pose(cur, pl.to, double(f - pl.grasp) / (pl.release - pl.grasp));
          if (f == pl.release) cur = p = pl.to;
        }
      if (noise > 0) p.translation() += Eigen::Vector3d(n(rng), n(rng), n(rng)) * noise;
      PoseSample& s = t.samples[k][f];
      s.valid = true;
      s.pose = p;
      s.confidence = 1.0;
      s.markers = 2;
    }
  }
  return t;
}

}  // namespace

TEST(ContactDetector, EventsAtTheRightFrames) {
  const PoseTracks t = make_tracks(120, {at(0, 0, 0.8), at(0.3, 0, 0.8)},
                                   {{0, 10, 40, at(0.2, 0.5, 1.3)}, {1, 55, 90, at(-0.1, 0.4, 1.3, 0.5)}});
  const ContactAnalysis a = detect_contacts(t);
  ASSERT_EQ(a.carries.size(), 2u);
  EXPECT_EQ(a.carries[0].object, 0);
  EXPECT_EQ(a.carries[0].start, 10);
  EXPECT_EQ(a.carries[0].end, 40);
  EXPECT_EQ(a.carries[1].start, 55);
  EXPECT_EQ(a.carries[1].end, 90);
  const Demonstration d = build_demonstration(t, a, "test");
  EXPECT_TRUE(validate(d).empty());
  ASSERT_EQ(d.events.size(), 4u);
  EXPECT_TRUE(d.events[1].poses[0].isApprox(at(0.2, 0.5, 1.3), 1e-6));  // released at its new rest
  EXPECT_TRUE(d.events[2].poses[1].isApprox(at(0.3, 0, 0.8), 1e-6));
}

TEST(ContactDetector, JitterMakesNoEventsAndTimingHolds) {
  const PoseTracks t = make_tracks(120, {at(0, 0, 0.8), at(0.3, 0, 0.8)}, {{1, 30, 70, at(0.4, 0.5, 1.3)}}, 0.0015, 7);
  const ContactAnalysis a = detect_contacts(t);
  ASSERT_EQ(a.carries.size(), 1u);
  EXPECT_LE(std::abs(a.carries[0].start - 30), 1);
  EXPECT_LE(std::abs(a.carries[0].end - 70), 2);
  EXPECT_NEAR(a.jitter_translation[0], 0.0015, 0.0008);
}

TEST(ContactDetector, PartHiddenWhileCarried) {
  PoseTracks t = make_tracks(100, {at(0, 0, 0.8)}, {{0, 20, 60, at(0.5, 0.2, 0.8)}});
  for (int f = 28; f < 55; ++f) t.samples[0][f].valid = false;  // behind something
  const ContactAnalysis a = detect_contacts(t);
  ASSERT_EQ(a.carries.size(), 1u);
  EXPECT_EQ(a.carries[0].start, 20);
  EXPECT_EQ(a.carries[0].end, 60);
  // Hidden from just before the grasp to after the release: the events still come out.
  for (int f = 18; f < 63; ++f) t.samples[0][f].valid = false;
  const ContactAnalysis b = detect_contacts(t);
  ASSERT_EQ(b.carries.size(), 1u);
  EXPECT_EQ(b.carries[0].start, 17);
  EXPECT_EQ(b.carries[0].end, 63);
}

TEST(ContactDetector, EventsHiddenByTheHandLieInsideTheGap) {
  PoseTracks t = make_tracks(100, {at(0, 0, 0.8)}, {{0, 20, 60, at(0.5, 0.2, 0.8)}});
  // Set down under the hand: last seen moving at 49, seen at rest from 66 on; a lone glimpse
  // at 58 (a marker corner between the fingers, its pose off) does not end the gap.
  for (int f = 50; f < 66; ++f) t.samples[0][f].valid = false;
  t.samples[0][58].valid = true;
  t.samples[0][58].pose = at(0.45, 0.25, 0.85);
  ContactAnalysis a = detect_contacts(t);
  ASSERT_EQ(a.carries.size(), 1u);
  EXPECT_EQ(a.carries[0].start, 20);
  EXPECT_EQ(a.carries[0].end, 49 + 11);  // 0.62 of the 17 frames from last seen moving to seen at rest
  // Picked up under the hand: last seen at rest at 14, seen moving from 27 on.
  for (int f = 15; f < 27; ++f) t.samples[0][f].valid = false;
  a = detect_contacts(t);
  ASSERT_EQ(a.carries.size(), 1u);
  EXPECT_EQ(a.carries[0].start, 27 - 8);  // 0.62 of the 13 frames hidden before it was seen moving
}

TEST(ContactDetector, APartSeenWhereItComesToRestBeforeTheGapWasSetDownAsItBegan) {
  PoseTracks t = make_tracks(100, {at(0, 0, 0.8)}, {{0, 20, 60, at(0.5, 0.2, 0.8)}});
  // Last seen at 49 8 mm from where it rests (its estimate turned 9 degrees by the hand over
  // it), hidden until 66: set down at 50, not 0.62 into the gap.
  for (int f = 50; f < 66; ++f) t.samples[0][f].valid = false;
  t.samples[0][48].pose = at(0.49, 0.19, 0.81, 0.0);
  t.samples[0][49].pose = at(0.5, 0.2, 0.808, 9.0 * M_PI / 180);
  ContactAnalysis a = detect_contacts(t);
  ASSERT_EQ(a.carries.size(), 1u);
  EXPECT_EQ(a.carries[0].end, 50);
  ContactDetectorOptions inside;
  inside.set_down_where_seen = false;
  a = detect_contacts(t, inside);
  ASSERT_EQ(a.carries.size(), 1u);
  EXPECT_EQ(a.carries[0].end, 49 + 11);
  // 3 cm away when last seen: still 0.62 into the gap.
  t.samples[0][49].pose = at(0.47, 0.2, 0.808);
  a = detect_contacts(t);
  ASSERT_EQ(a.carries.size(), 1u);
  EXPECT_EQ(a.carries[0].end, 49 + 11);
}

TEST(ContactDetector, AnEstimateThatJumpsAsTheHandArrivesIsStillTheRest) {
  // The hand arriving turns the estimate 3 degrees at 17 (waiter_0's sugar box without
  // markers); it sits there until the hand hides the part at 20 and is seen moving from 30 on.
  PoseTracks t = make_tracks(100, {at(0, 0, 0.8)}, {{0, 20, 60, at(0.5, 0.2, 0.8)}});
  for (int f = 17; f < 20; ++f) t.samples[0][f].pose = at(0.0015, 0, 0.8, 3.0 * M_PI / 180);
  for (int f = 20; f < 30; ++f) t.samples[0][f].valid = false;
  ContactAnalysis a = detect_contacts(t);
  ASSERT_EQ(a.carries.size(), 1u);
  EXPECT_EQ(a.carries[0].start, 19);  // its last frame at rest, not the last before the jump (16)
  EXPECT_EQ(a.carries[0].end, 60);
  // Samples that rise 2 mm a frame (6-10 mm up) before the gap are the start of a slow lift, not a rest.
  for (int f = 17; f < 20; ++f) t.samples[0][f].pose = at(0, 0, 0.804 + 0.002 * (f - 16));
  a = detect_contacts(t);
  ASSERT_EQ(a.carries.size(), 1u);
  EXPECT_EQ(a.carries[0].start, 16);
}

TEST(ContactDetector, ACarryNeverSeenToEndIsSaid) {
  // Put down where the camera cannot see it: last seen moving at 49, never again.
  PoseTracks t = make_tracks(100, {at(0, 0, 0.8)}, {{0, 20, 60, at(0.5, 0.2, 0.8)}});
  for (int f = 50; f < 100; ++f) t.samples[0][f].valid = false;
  const ContactAnalysis a = detect_contacts(t);
  ASSERT_EQ(a.carries.size(), 1u);
  EXPECT_EQ(a.carries[0].end, 49);
  EXPECT_FALSE(a.carries[0].seen_at_rest_after);
  std::vector<std::string> warnings;
  build_demonstration(t, a, "t", {}, &warnings);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("P0 at frames 20-49: carried and never seen at rest after"), std::string::npos) << warnings[0];
  // Seen at rest again: no warning.
  const ContactAnalysis b = detect_contacts(make_tracks(100, {at(0, 0, 0.8)}, {{0, 20, 60, at(0.5, 0.2, 0.8)}}));
  ASSERT_EQ(b.carries.size(), 1u);
  EXPECT_TRUE(b.carries[0].seen_at_rest_after);
}

TEST(ContactDetector, OneFarMarkerIsPreciseFromFrameToFrame) {
  // One small marker far away: 17 mm expected error along the line of sight, but the same
  // error in every frame while the part rests. The grasp and release are where it moves.
  PoseTracks t = make_tracks(120, {at(0, 0, 0.8)}, {{0, 40, 80, at(0.4, 0.1, 0.8)}});
  for (auto& s : t.samples[0]) {
    s.markers = 1;
    s.marker_set = 1u << 7;
    s.reprojection_px = 0.04;
    s.sigma_translation = 0.017;
    s.sigma_rotation = 0.023;
  }
  const ContactAnalysis a = detect_contacts(t);
  ASSERT_EQ(a.carries.size(), 1u);
  EXPECT_NEAR(a.carries[0].start, 40, 1);
  EXPECT_NEAR(a.carries[0].end, 80, 2);
  // Seen through another marker for a while, the estimate jumps by 10 mm: no event.
  PoseTracks b = make_tracks(120, {at(0, 0, 0.8)}, {});
  for (int f = 0; f < 120; ++f) {
    PoseSample& s = b.samples[0][f];
    s.markers = 1;
    s.reprojection_px = 0.04;
    s.sigma_translation = 0.012;
    s.sigma_rotation = 0.02;
    const bool other = f >= 50 && f < 70;
    s.marker_set = other ? 1u << 3 : 1u << 7;
    if (other) s.pose.translation().z() += 0.010;
  }
  const ContactAnalysis c = detect_contacts(b);
  EXPECT_TRUE(c.carries.empty());
}

TEST(ContactDetector, PartsRidingOnATrayMakeNoEvents) {
  PoseTracks t = make_tracks(100, {at(0, 0, 0.8), at(0.2, 0, 0.8)}, {});
  for (int f = 30; f < 100; ++f)
    for (int k = 0; k < 2; ++k) {
      const double s = std::min(1.0, (f - 30) / 30.0);
      t.samples[k][f].pose.translation() += Eigen::Vector3d(0, 1.2 * s, 0);
    }
  const ContactAnalysis a = detect_contacts(t);
  EXPECT_TRUE(a.carries.empty());
  EXPECT_EQ(a.transports.size(), 2u);
}

TEST(ContactDetector, PartsOnATurningTrayRideEvenWithOrientationErrors) {
  // waiter_0 without markers: two small parts 0.8 m apart ride a tray that goes 1.1 m and turns
  // 10 degrees; the far part's orientation estimate wobbles by 3 degrees, which swings the other
  // part's position in its frame by 4 cm, beyond co_motion_tolerance.
  PoseTracks t = make_tracks(100, {at(0.4, 0, 0.8), at(-0.4, 0, 0.8)}, {});
  for (int f = 30; f < 100; ++f) {
    const double s = std::min(1.0, (f - 30) / 30.0);
    const Pose ride = at(0, 1.1 * s, 0, 10.0 * M_PI / 180 * s);
    for (int k = 0; k < 2; ++k) t.samples[k][f].pose = ride * t.samples[k][f].pose;
    const double wobble = (f % 2 ? 3.0 : -3.0) * M_PI / 180;
    t.samples[0][f].pose.linear() = t.samples[0][f].pose.linear() * Eigen::AngleAxisd(wobble, Eigen::Vector3d::UnitZ());
  }
  const ContactAnalysis a = detect_contacts(t);
  EXPECT_TRUE(a.carries.empty());
  EXPECT_EQ(a.transports.size(), 2u);
  ContactDetectorOptions relative_only;
  relative_only.co_motion_displacement = 0.0;
  EXPECT_EQ(detect_contacts(t, relative_only).carries.size(), 1u);  // without the displacement rule: a carry
}

TEST(ContactDetector, ShortExcursionsAndBadFitsAreIgnored) {
  PoseTracks t = make_tracks(80, {at(0, 0, 0.8)}, {});
  for (int f = 30; f < 33; ++f) t.samples[0][f].pose.translation().x() += 0.06;  // a 3-frame glitch
  for (auto& s : t.samples[0]) s.reprojection_px = 0.1;
  for (int f = 50; f < 60; ++f) {  // a partly hidden marker: a pose far off, fitting badly
    t.samples[0][f].pose.translation().z() += 0.2;
    t.samples[0][f].reprojection_px = 1.2;
  }
  const ContactAnalysis a = detect_contacts(t);
  EXPECT_TRUE(a.carries.empty());
  EXPECT_TRUE(a.transports.empty());
}

TEST(ContactDetector, OneObjectAtATime) {
  // Two parts "move" at once without keeping their relative pose: the farther one is carried.
  const PoseTracks t = make_tracks(100, {at(0, 0, 0.8), at(0.3, 0, 0.8)},
                                   {{0, 20, 60, at(0.0, 0.8, 1.3)}, {1, 30, 50, at(0.35, 0.0, 0.8)}});
  const ContactAnalysis a = detect_contacts(t);
  ASSERT_EQ(a.carries.size(), 1u);
  EXPECT_EQ(a.carries[0].object, 0);
  EXPECT_EQ(a.rejected.size(), 1u);
}

TEST(ContactDetector, APartSetDownUnseenBeforeAnotherIsTakenWasReleasedInItsGap) {
  // P0 carried 10-40, last seen moving at 20, seen at rest again from 46 (hidden behind P1 and
  // the hand); P1 taken at 30 in plain view and carried to 50. One hand: P0 was set down before
  // 30, 0.62 of the way from 20; its carry does not overlap P1's, and both are kept.
  PoseTracks t = make_tracks(100, {at(0, 0, 0.8), at(0.3, 0, 0.8)},
                             {{0, 10, 40, at(0.6, 0.8, 0.8)}, {1, 30, 50, at(0.3, 0.3, 0.8)}});
  for (int f = 21; f < 46; ++f) t.samples[0][f].valid = false;
  const ContactAnalysis a = detect_contacts(t);
  ASSERT_EQ(a.carries.size(), 2u);
  EXPECT_EQ(a.carries[0].object, 0);
  EXPECT_EQ(a.carries[0].start, 10);
  EXPECT_EQ(a.carries[0].end, 20 + 6);  // 0.62 of the 10 frames from last seen to P1's grasp
  EXPECT_LE(a.carries[0].end_confidence, 0.5);
  EXPECT_EQ(a.carries[1].object, 1);
  EXPECT_EQ(a.carries[1].start, 30);
  EXPECT_TRUE(a.rejected.empty());
  // Seen moving on while P1 is taken (both in plain view): one of them is rejected, as before.
  t.samples[0][32].valid = true;
  const ContactAnalysis b = detect_contacts(t);
  EXPECT_EQ(b.carries.size(), 1u);
  EXPECT_EQ(b.rejected.size(), 1u);
}

TEST(TrackSmoothing, NoLagAtTheEvents) {
  const PoseTracks t = make_tracks(100, {at(0, 0, 0.8)}, {{0, 20, 60, at(0.5, 0.2, 0.8)}}, 0.001, 3);
  const ContactAnalysis a = detect_contacts(t);
  const PoseTracks s = smooth_tracks(t, a);
  // Constant through each rest, right up to the event frames.
  EXPECT_TRUE(s.samples[0][0].pose.isApprox(s.samples[0][a.carries[0].start].pose, 1e-12));
  EXPECT_TRUE(s.samples[0][99].pose.isApprox(s.samples[0][a.carries[0].end].pose, 1e-12));
  // Moving right after the grasp (a lagging filter would still be at the rest pose).
  const Pose truth = carry_pose(at(0, 0, 0.8), at(0.5, 0.2, 0.8), 3.0 / 40);
  EXPECT_LT((s.samples[0][23].pose.translation() - truth.translation()).norm(), 0.004);
}
