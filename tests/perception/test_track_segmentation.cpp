// Segmentation of noisy pose tracks into rests, carries and rides: each kind of noise the real
// benchmark tracks show, built as a small track with the events it must give.
#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "core/demo/benchmark_scene.h"
#include "core/demo/benchmark_task.h"
#include "core/error.h"
#include "perception/events/track_segmentation.h"
#include "perception/events/tracks_demonstration.h"

namespace demoplan::perception {
namespace {

constexpr int kFrames = 80;

// Part tracks in metres; noise is Gaussian with `sigma` per axis, larger along y (the camera
// ray of these tracks) by `depth_factor`.
struct TrackBuilder {
  PoseTracks tracks;
  std::mt19937 rng{7};

  TrackBuilder() { tracks.frames = kFrames; }

  int add(const std::string& id, bool planning = true) {
    tracks.object_ids.push_back(id);
    tracks.planning.push_back(planning);
    tracks.samples.emplace_back(kFrames);
    return static_cast<int>(tracks.object_ids.size()) - 1;
  }
  void set(int o, int f, const Eigen::Vector3d& p, double sigma = 0.0, double depth_factor = 1.0) {
    std::normal_distribution<double> n(0.0, sigma);
    PoseSample& s = tracks.samples[o][f];
    s.valid = true;
    s.confidence = 1.0;
    s.pose = Pose::Identity();
    s.pose.translation() = p + Eigen::Vector3d(n(rng), depth_factor * n(rng), n(rng));
  }
  // Rest at `a` until `grasp` (inclusive), a carry to `b`, rest at `b` from `release` on.
  void carry(int o, const Eigen::Vector3d& a, const Eigen::Vector3d& b, int grasp, int release, double sigma = 0.002,
             double depth_factor = 1.0, int from = 0, int to = kFrames - 1) {
    for (int f = from; f <= to; ++f) {
      // At constant speed: the part leaves its rest right after `grasp`, well beyond the noise.
      const double s = std::clamp(double(f - grasp) / double(release - grasp), 0.0, 1.0);
      set(o, f, a + s * (b - a), sigma, depth_factor);
    }
  }
};

std::vector<TrackSegment> of_kind(const TrackSegmentation& s, int o, SegmentKind kind) {
  std::vector<TrackSegment> out;
  for (const auto& x : s.objects[o].segments)
    if (x.kind == kind) out.push_back(x);
  return out;
}

TEST(TrackSegmentation, ARestWithDriftAndAnOutlierGivesOneCarry) {
  TrackBuilder b;
  const int o = b.add("part");
  const Eigen::Vector3d A(0.2, 0.4, 0.85), B(0.5, 0.7, 1.3);
  b.carry(o, A, B, 29, 50, 0.002, 3.0);
  // Centimetres of drift while resting, an outlier of 30 cm, a jump of 2 cm for three frames.
  for (int f = 0; f <= 29; ++f) b.tracks.samples[o][f].pose.translation().y() += 0.012 * f / 29.0;
  b.tracks.samples[o][10].pose.translation() += Eigen::Vector3d(0.3, -0.1, 0.05);
  for (int f = 60; f < 63; ++f) b.tracks.samples[o][f].pose.translation().x() += 0.02;
  const TrackSegmentation s = segment_tracks(b.tracks);
  const auto carries = s.contacts(b.tracks).carries;
  ASSERT_EQ(carries.size(), 1u);
  EXPECT_EQ(carries[0].start, 29);  // grasp: the last frame at rest
  EXPECT_EQ(carries[0].end, 50);    // release: the first frame at rest again
  EXPECT_NEAR(carries[0].distance, (B - A).norm(), 0.03);
  const auto rests = of_kind(s, o, SegmentKind::Rest);
  ASSERT_EQ(rests.size(), 2u);
  EXPECT_LT((rests[1].pose.translation() - B).norm(), 0.005);
  // The noise measured along the depth direction is the larger one.
  EXPECT_GT(s.objects[o].noise.sigma_max, 2.0 * s.objects[o].noise.sigma_min);
  EXPECT_TRUE(s.doubts.empty());
}

// tunnel_0's second release: the part stops, then the detector's orientation flips by 103 and
// 166 degrees for single frames while its position estimate shifts by 6 mm at the first flip
// and holds there within 0.5 mm. The samples before the shift are as much the rest as those
// after: the release is where the part stopped, not where the estimate settled.
TEST(TrackSegmentation, AFlipThatShiftsARestingPartsEstimateKeepsTheReleaseWhereItStopped) {
  TrackBuilder b;
  const int o = b.add("part");
  b.tracks.frames = 55;
  b.tracks.samples[o].resize(55);
  const Eigen::Vector3d A(0.2, 0.4, 0.85), B(-0.246, 0.228, 0.841);
  b.carry(o, A, B + Eigen::Vector3d(-0.002, -0.003, 0.002), 19, 45, 0.0, 1.0, 0, 44);
  // The samples of tunnel_0's frames 70-79 about where the estimate settles (mm).
  const double offsets[10][3] = {{-2.0, -3.2, 1.7}, {-0.1, -3.9, 2.3}, {4.0, -4.2, 1.8}, {4.2, -4.5, 1.8},
                                 {-0.4, 0.1, 0.0},  {0.0, 0.0, 0.1},   {-0.3, 0.1, 0.0},  {0.4, -0.1, 0.0},
                                 {0.1, 0.2, 0.0},   {-0.6, 0.4, -0.2}};
  for (int k = 0; k < 10; ++k) b.set(o, 45 + k, B + 0.001 * Eigen::Vector3d(offsets[k][0], offsets[k][1], offsets[k][2]));
  b.tracks.samples[o][49].pose.linear() = Eigen::AngleAxisd(103.0 * M_PI / 180.0, Eigen::Vector3d(0.3, 0.9, 0.3).normalized()).toRotationMatrix();
  b.tracks.samples[o][51].pose.linear() = Eigen::AngleAxisd(166.0 * M_PI / 180.0, Eigen::Vector3d(0.9, 0.1, 0.4).normalized()).toRotationMatrix();
  const TrackSegmentation s = segment_tracks(b.tracks);
  const auto carries = s.contacts(b.tracks).carries;
  ASSERT_EQ(carries.size(), 1u);
  EXPECT_EQ(carries[0].start, 19);
  EXPECT_EQ(carries[0].end, 45);  // the first frame at rest
  const auto rests = of_kind(s, o, SegmentKind::Rest);
  ASSERT_EQ(rests.size(), 2u);  // the flips and the shift make no motion
  EXPECT_EQ(rests[1].first, 45);
  EXPECT_EQ(rests[1].last, 54);
  EXPECT_LT((rests[1].pose.translation() - B).norm(), 0.005);
}

TEST(TrackSegmentation, ACarryWithADropoutKeepsItsEvents) {
  TrackBuilder b;
  const int o = b.add("part");
  b.carry(o, {0.2, 0.4, 0.85}, {0.6, 0.4, 0.85}, 20, 45);
  for (int f = 28; f <= 38; ++f) b.tracks.samples[o][f].valid = false;
  const auto carries = segment_tracks(b.tracks).contacts(b.tracks).carries;
  ASSERT_EQ(carries.size(), 1u);
  EXPECT_EQ(carries[0].start, 20);
  EXPECT_EQ(carries[0].end, 45);
}

TEST(TrackSegmentation, APartHiddenWhileCarriedIsACarryWithADoubt) {
  TrackBuilder b;
  const int o = b.add("part");
  b.carry(o, {0.2, 0.4, 0.85}, {0.6, 0.4, 0.85}, 20, 45);
  for (int f = 21; f <= 44; ++f) b.tracks.samples[o][f].valid = false;
  const TrackSegmentation s = segment_tracks(b.tracks);
  const auto carries = s.contacts(b.tracks).carries;
  ASSERT_EQ(carries.size(), 1u);
  EXPECT_EQ(carries[0].start, 20);
  EXPECT_EQ(carries[0].end, 45);
  ASSERT_EQ(s.doubts.size(), 1u);
  EXPECT_EQ(s.doubts[0].first, 21);
  EXPECT_EQ(s.doubts[0].last, 44);
  EXPECT_NE(s.doubts[0].message.find("two places"), std::string::npos) << s.doubts[0].message;
}

TEST(TrackSegmentation, PartsRidingATrayMakeNoEventsAndTheCarryOntoItEndsWhereTheRideStarts) {
  TrackBuilder b;
  const int tray = b.add("TRAY", false), rider = b.add("rider"), placed = b.add("placed");
  const Eigen::Vector3d t0(0.5, 1.2, 0.0), t1(0.5, 2.1, 0.0);
  b.carry(tray, t0, t1, 45, 60, 0.0);
  // `rider` stands on the tray from the start; `placed` is carried onto it just before it moves,
  // with no rest in the world between (the tray starts moving as the hand lets go).
  const Eigen::Vector3d on_tray(0.05, -0.1, 0.87);
  b.carry(rider, t0 + on_tray, t1 + on_tray, 45, 60);
  b.carry(placed, {0.8, 0.4, 0.9}, t0 + Eigen::Vector3d(-0.05, 0.1, 0.87), 20, 45, 0.002, 1.0, 0, 45);
  b.carry(placed, t0 + Eigen::Vector3d(-0.05, 0.1, 0.87), t1 + Eigen::Vector3d(-0.05, 0.1, 0.87), 45, 60, 0.002, 1.0, 46);
  const TrackSegmentation s = segment_tracks(b.tracks);
  const ContactAnalysis c = s.contacts(b.tracks);
  ASSERT_EQ(c.carries.size(), 1u);  // the tray is no planning part; the rider is never carried
  EXPECT_EQ(c.carries[0].object, placed);
  EXPECT_EQ(c.carries[0].start, 20);
  EXPECT_NEAR(c.carries[0].end, 45, 1);
  EXPECT_EQ(of_kind(s, rider, SegmentKind::Ride).size(), 1u);
  ASSERT_EQ(of_kind(s, placed, SegmentKind::Ride).size(), 1u);
  EXPECT_EQ(of_kind(s, placed, SegmentKind::Ride)[0].carrier, tray);
}

TEST(TrackSegmentation, AJumpOfAnotherPartDuringACarryIsNoCarry) {
  TrackBuilder b;
  const int carried = b.add("carried"), other = b.add("other");
  b.carry(carried, {0.2, 0.4, 0.85}, {0.7, 0.4, 0.85}, 20, 50);
  b.carry(other, {0.4, 0.6, 0.85}, {0.4, 0.6, 0.85}, 0, 1);
  // The carried part passes in front of the other: its estimate jumps by 15 cm for six frames.
  for (int f = 33; f < 39; ++f) b.tracks.samples[other][f].pose.translation().y() += 0.15;
  const auto carries = segment_tracks(b.tracks).contacts(b.tracks).carries;
  ASSERT_EQ(carries.size(), 1u);
  EXPECT_EQ(carries[0].object, carried);
}

TEST(TrackSegmentation, OfTwoPartsCarriedAtOnceTheShorterMoveIsADoubt) {
  TrackBuilder b;
  const int far = b.add("far"), near = b.add("near");
  b.carry(far, {0.2, 0.4, 0.85}, {0.8, 0.4, 0.85}, 20, 50);
  b.carry(near, {0.4, 0.8, 0.85}, {0.4, 1.0, 0.85}, 30, 40);
  const TrackSegmentation s = segment_tracks(b.tracks);
  const auto carries = s.contacts(b.tracks).carries;
  ASSERT_EQ(carries.size(), 1u);
  EXPECT_EQ(carries[0].object, far);
  ASSERT_EQ(s.doubts.size(), 1u);
  EXPECT_EQ(s.doubts[0].object, near);
  EXPECT_NE(s.doubts[0].message.find("one hand"), std::string::npos) << s.doubts[0].message;
}

TEST(TrackSegmentation, ACarryOutOfViewIsADoubt) {
  TrackBuilder b;
  const int o = b.add("part");
  // Carried out of the camera's view: not seen after frame 63. (Seen moving steadily over five
  // frames or more, slower than about 3 cm a frame, the last frames would pass for a wide rest.)
  b.carry(o, {0.2, 0.4, 0.85}, {0.9, 0.4, 0.85}, 60, 100);
  for (int f = 64; f < kFrames; ++f) b.tracks.samples[o][f].valid = false;
  const TrackSegmentation s = segment_tracks(b.tracks);
  EXPECT_TRUE(s.contacts(b.tracks).carries.empty());
  ASSERT_EQ(s.doubts.size(), 1u);
  EXPECT_EQ(s.doubts[0].last, kFrames - 1);
  EXPECT_EQ(s.doubts[0].first, 64);
  EXPECT_NE(s.doubts[0].message.find("not seen after frame 63"), std::string::npos) << s.doubts[0].message;
}

TEST(TrackSegmentation, BrokenSamplesAreIgnoredAndNamed) {
  TrackBuilder b;
  const int o = b.add("YCBV_05");
  b.carry(o, {0.2, 0.4, 0.85}, {0.6, 0.4, 0.85}, 20, 45);
  b.tracks.samples[o][7].pose(0, 3) = std::nan("");
  b.tracks.samples[o][12].pose.linear() *= 1.5;  // not a rotation
  const TrackSegmentation s = segment_tracks(b.tracks);
  const auto carries = s.contacts(b.tracks).carries;
  ASSERT_EQ(carries.size(), 1u);
  EXPECT_EQ(carries[0].start, 20);
  ASSERT_EQ(s.doubts.size(), 1u);
  EXPECT_EQ(s.doubts[0].first, 7);
  EXPECT_EQ(s.doubts[0].last, 12);
  EXPECT_NE(s.doubts[0].message.find("YCBV_05: frames 7, 12"), std::string::npos) << s.doubts[0].message;
}

TEST(TrackSegmentation, ATrackShorterThanTheVideoAndAPartThatNeverMoves) {
  TrackBuilder b;
  const int moved = b.add("moved"), still = b.add("still");
  b.carry(moved, {0.2, 0.4, 0.85}, {0.6, 0.4, 0.85}, 20, 45);
  b.carry(still, {0.4, 0.9, 0.85}, {0.4, 0.9, 0.85}, 0, 1);
  b.tracks.samples[moved].resize(60);  // the track ends before the video does
  const TrackSegmentation s = segment_tracks(b.tracks);
  const auto carries = s.contacts(b.tracks).carries;
  ASSERT_EQ(carries.size(), 1u);
  EXPECT_EQ(carries[0].end, 45);
  ASSERT_EQ(s.doubts.size(), 1u);  // the short track ends 20 frames early
  EXPECT_EQ(s.doubts[0].object, moved);
  EXPECT_EQ(s.doubts[0].first, 60);
  ASSERT_EQ(s.objects[still].segments.size(), 1u);
  EXPECT_EQ(s.objects[still].segments[0].kind, SegmentKind::Rest);
  EXPECT_EQ(s.objects[still].segments[0].last, kFrames - 1);
}

// The real tracks: shelf_1's events and picks from objects_poses alone, with the labels
// erased so that reading them would show.
TEST(TracksDemonstration, Shelf1FromItsTracksAloneHasTheLabelledPicks) {
  BenchmarkTask task = load_benchmark_task(DEMOPLAN_DATA_DIR, "shelf_1");
  const auto labelled = contact_segments(task);
  for (auto& c : task.contacts) std::fill(c.begin(), c.end(), false);
  task.subgoal_poses.clear();
  const Scene scene = build_benchmark_scene(task, "panda", 0);
  const TracksDemonstration found = demonstration_from_tracks(task, scene);
  const auto segments = carries_as_segments(found.tracks, found.segmentation);
  ASSERT_EQ(segments.size(), labelled.size());
  for (size_t k = 0; k < segments.size(); ++k) {
    EXPECT_EQ(segments[k].object, labelled[k].object);
    EXPECT_NEAR(segments[k].first, labelled[k].first, 5);
    EXPECT_NEAR(segments[k].last + 1, labelled[k].last + 1, 8);
  }
  EXPECT_EQ(found.demonstration.events.size(), 2 * labelled.size());
}

TEST(TracksDemonstration, TracksWhereNothingMovesAreAnErrorNamingTheFile) {
  BenchmarkTask task = load_benchmark_task(DEMOPLAN_DATA_DIR, "shelf_0");
  for (auto& row : task.raw_poses) std::fill(row.begin(), row.end(), row.front());
  const Scene scene = build_benchmark_scene(task, "panda", 0);
  try {
    demonstration_from_tracks(task, scene);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("shelf_0.json"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("objects_poses"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace demoplan::perception
