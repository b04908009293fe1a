// A tray carried with parts on it, 2.4 m from the camera as waiter_0's: its depth from its own
// image is a percent off, but the pattern its riders make holds the ride, and the riders rest
// where the ride took them.
#include <gtest/gtest.h>

#include <cmath>

#include "perception/camera/look_at.h"
#include "perception/extraction/carrier_rides.h"
#include "perception/tracking/carrier_ride.h"

using namespace demoplan;
using namespace demoplan::perception;

namespace {

Camera waiter_camera() {
  Camera c;
  c.fx = c.fy = 1100;
  c.cx = 639.5, c.cy = 359.5;
  c.world_T_camera = look_at(Eigen::Vector3d(-1.6, 1.6, 2.0), Eigen::Vector3d(0.5, 1.8, 0.7));
  return c;
}

Eigen::Vector2d pixel(const Camera& c, const Eigen::Vector3d& world) {
  const cv::Point2d q = c.project(c.world_T_camera->inverse() * world);
  return {q.x, q.y};
}

// `p` moved by `metres` along its line of sight from the camera (away from it when positive).
Eigen::Vector3d along_sight(const Camera& c, const Eigen::Vector3d& p, double metres) {
  return p + metres * (p - c.world_T_camera->translation()).normalized();
}

Pose at(const Eigen::Vector3d& t, double yaw = 0.0) {
  Pose P = Pose::Identity();
  P.linear() = Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  P.translation() = t;
  return P;
}

// waiter_0's ride: the tray turned 11 degrees and carried 1.1 m along the table and 4 cm down.
struct Ride {
  Camera camera = waiter_camera();
  Pose tray_before = at({0.445, 0.936, 0.693});
  Pose motion = at({0.0, 0.0, 0.0});
  std::vector<Pose> riders_before{at({0.349, 0.563, 0.833}, 0.2), at({0.605, 1.224, 0.791}, 0.3), at({0.420, 1.342, 0.797}, -1.0)};
  Ride() {
    const Pose turn = at({0, 0, 0}, -0.199);
    const Eigen::Vector3d shift(0.012, 1.090, -0.041);
    // Turned about the tray's centre, then shifted.
    motion = at(shift + tray_before.translation()) * turn * at(-tray_before.translation());
  }
  Pose tray_after() const { return motion * tray_before; }
  std::vector<RiderSighting> sightings() const {
    std::vector<RiderSighting> s;
    for (const Pose& r : riders_before) s.push_back({r.translation(), pixel(camera, (motion * r).translation())});
    return s;
  }
  // The tray as its image alone puts it: 27 mm too far, turned a degree off.
  Pose tray_tracked() const {
    Pose P = tray_after() * at({0, 0, 0}, 0.017);
    P.translation() = along_sight(camera, tray_after().translation(), 0.027);
    return P;
  }
};

TEST(CarrierRide, TheRideIsWhereItsRidersPatternFits) {
  const Ride ride;
  const RideFit fit = fit_ride(ride.camera, ride.tray_before, ride.tray_tracked(), ride.sightings());
  ASSERT_TRUE(fit.motion);
  EXPECT_LT(fit.residual_px, 1e-3);
  const Pose* motion = &*fit.motion;
  EXPECT_LT(((*motion * ride.tray_before).translation() - ride.tray_after().translation()).norm(), 1e-4);
  for (const Pose& r : ride.riders_before)
    EXPECT_LT(((*motion * r).translation() - (ride.motion * r).translation()).norm(), 1e-4);
  EXPECT_LT(Eigen::AngleAxisd((*motion).linear() * ride.motion.linear().transpose()).angle(), 1e-4);
  // A pixel of noise on each rider: still within millimetres, where the tray's image put it 27.
  std::vector<RiderSighting> noisy = ride.sightings();
  for (size_t i = 0; i < noisy.size(); ++i) noisy[i].seen += Eigen::Vector2d(i % 2 ? 1.0 : -1.0, i == 1 ? 1.0 : -0.5);
  const auto rough = fit_ride(ride.camera, ride.tray_before, ride.tray_tracked(), noisy).motion;
  ASSERT_TRUE(rough);
  const double off = ((*rough * ride.tray_before).translation() - ride.tray_after().translation()).norm();
  EXPECT_LT(off, 0.010);
  EXPECT_GT((ride.tray_tracked().translation() - ride.tray_after().translation()).norm(), 0.025);
}

TEST(CarrierRide, PartsThatDidNotMoveAsOneOrOneAloneGiveNoFit) {
  const Ride ride;
  // One rider slid 10 cm across the tray during the ride.
  std::vector<RiderSighting> slid = ride.sightings();
  slid[1].seen = pixel(ride.camera, (ride.motion * at({0.1, 0, 0}) * ride.riders_before[1]).translation());
  const RideFit off = fit_ride(ride.camera, ride.tray_before, ride.tray_tracked(), slid);
  EXPECT_FALSE(off.motion);
  EXPECT_GT(off.residual_px, 3.0);
  // One rider does not tell a turn from a shift.
  const RideFit alone = fit_ride(ride.camera, ride.tray_before, ride.tray_tracked(), {ride.sightings()[0]});
  EXPECT_FALSE(alone.motion);
  EXPECT_EQ(alone.residual_px, -1.0);
  // No camera pose: nothing to project with.
  Camera unplaced = ride.camera;
  unplaced.world_T_camera.reset();
  EXPECT_FALSE(fit_ride(unplaced, ride.tray_before, ride.tray_tracked(), ride.sightings()).motion);
}

// The extraction's part: the riders' rests before (the last event before the ride), the ride
// from the transports, the riders' places at the events after it while they rest there.
TEST(CarrierRides, RidersRestWhereTheRideTookThemUntilTheyAreCarriedOn) {
  const Ride ride;
  const int frames = 60, start = 20, end = 30, grasp = 40;
  const std::vector<TrackedPart> parts{{"A", true, {}}, {"B", true, {}}, {"C", true, {}}, {"TRAY", false, {}}};
  PoseTracks tracks;
  tracks.object_ids = {"A", "B", "C", "TRAY"};
  tracks.planning = {true, true, true, false};
  tracks.resize(frames);
  // Each part's own image puts it up to 35 mm off along its line of sight after the ride.
  const double depth_error[] = {0.035, -0.030, 0.020, 0.027};
  auto sample = [&](size_t k, int f) {
    const Pose before = k < 3 ? ride.riders_before[k] : ride.tray_before;
    PoseSample s;
    s.valid = f != start + 1;  // hidden as the ride starts
    s.confidence = 1.0;
    const double t = std::clamp(double(f - start) / (end - start), 0.0, 1.0);
    s.pose = interpolate(before, ride.motion * before, t);
    if (f >= end) s.pose.translation() = along_sight(ride.camera, s.pose.translation(), depth_error[k]);
    return s;
  };
  for (size_t k = 0; k < 4; ++k)
    for (int f = 0; f < frames; ++f) tracks.samples[k][f] = sample(k, f);
  ContactAnalysis contacts;
  for (int k = 0; k < 4; ++k) contacts.transports.push_back({.object = k, .start = start, .end = end});
  contacts.carries.push_back({.object = 0, .start = grasp, .end = grasp + 10});
  // Demonstration: a release before the ride, A's grasp after it and its release after that.
  Demonstration d;
  d.object_ids = {"A", "B", "C"};
  auto event = [&](int frame, EventType type) {
    ContactEvent e;
    e.frame = frame, e.object = 0, e.type = type;
    for (size_t k = 0; k < 3; ++k) e.poses.push_back(tracks.samples[k][frame].pose);
    return e;
  };
  d.events = {event(10, EventType::Release), event(grasp, EventType::Grasp), event(grasp + 10, EventType::Release)};
  const Pose a_turned = d.events[1].poses[0];

  std::vector<std::string> notes;
  const auto rides = fit_carrier_rides(tracks, contacts, parts, d, Scene{}, SnapOptions{}, ride.camera, {}, &notes);
  ASSERT_EQ(rides.size(), 1u);
  ASSERT_EQ(notes.size(), 1u);
  EXPECT_EQ(notes[0].substr(0, 28), "part 'TRAY', frames 20-30: i") << notes[0];
  EXPECT_NE(notes[0].find("27 mm nearer than its own image puts it"), std::string::npos) << notes[0];
  EXPECT_EQ(rides[0].carrier, 3u);
  EXPECT_EQ(rides[0].riders.size(), 3u);
  EXPECT_LT((rides[0].carrier_after.translation() - ride.tray_after().translation()).norm(), 1e-3);
  move_riders(d, rides);
  for (size_t k = 0; k < 3; ++k)
    EXPECT_LT((d.events[1].poses[k].translation() - (ride.motion * ride.riders_before[k]).translation()).norm(), 1e-3)
        << "part " << k << " at its grasp after the ride";
  EXPECT_TRUE(d.events[1].poses[0].linear().isApprox(a_turned.linear())) << "turned as its own rest shows it";
  // A is carried on from the tray (its release's pose is its own); B and C still rest there.
  EXPECT_TRUE(d.events[2].poses[0].isApprox(tracks.samples[0][grasp + 10].pose));
  EXPECT_LT((d.events[2].poses[1].translation() - (ride.motion * ride.riders_before[1]).translation()).norm(), 1e-3);
  // The event before the ride is left as it was.
  EXPECT_TRUE(d.events[0].poses[2].isApprox(ride.riders_before[2]));
}

}  // namespace
