#pragma once
// The rides of the carriers (parts not planned for: a tray carried with parts on it), fitted to
// where their riders show after them (carrier_ride.h), and what they did to the demonstration: a
// rider resting where its ride left it rests where the ride took it (its depth from its own
// image is centimetres off a few metres away; the ride's, fitted to all of them, is not), turned
// as its own rest there shows it (a rest's turn is measured well: rest_turn), and the carrier's
// top there is what parts put on it are settled on.
// A rider is a planning part that rode over the same frames; its pose before is its settled
// pose at the last event before the ride (on the carrier, which rested on the furniture), where
// it shows after is its track's image position in the first frames it rests after the ride.
#include <string>
#include <vector>

#include "core/demo/demonstration.h"
#include "core/demo/rest_pose.h"
#include "core/scene/scene.h"
#include "perception/events/contact_detector.h"
#include "perception/tracking/carrier_ride.h"
#include "perception/tracking/pose_tracker.h"

namespace demoplan::perception {

struct RiderRest {
  int object = -1;  // index into the demonstration's object_ids
  Pose before = Pose::Identity();  // world
  int until = 0;    // the last frame it rests where the ride left it (its next grasp, or the carrier moving on)
};

struct FittedRide {
  size_t carrier = 0;  // index into the tracker's parts
  int end = 0;         // the first frame at rest after the ride
  int until = 0;       // the last frame the carrier rests where the ride left it
  Pose motion = Pose::Identity();   // world: a pose after the ride is the motion times the pose before
  Pose carrier_after = Pose::Identity();
  std::vector<RiderRest> riders;
};

// `settled`: the demonstration with its rests settled on the furniture and the carriers' tracked
// tops; a carrier's pose before its ride is settled onto the furniture with `snap` where it can be.
// `notes`: for the operator, each ride fitted and each whose riders did not fit one motion.
std::vector<FittedRide> fit_carrier_rides(const PoseTracks& tracks, const ContactAnalysis& contacts,
                                          const std::vector<TrackedPart>& parts, const Demonstration& settled,
                                          const Scene& scene, const SnapOptions& snap, const Camera& camera,
                                          const CarrierRideOptions& options = {}, std::vector<std::string>* notes = nullptr);

// Every rider's place at the events from its ride's end while it rests where the ride left it:
// its place before, moved by the ride.
void move_riders(Demonstration& demonstration, const std::vector<FittedRide>& rides);

}  // namespace demoplan::perception
