#pragma once
// Rests and carries of noisy pose tracks, without contact labels: what a real detector's per-frame
// poses say about when each part was picked up and put down.
//
// Per part, the track is cut into rests (the pose constant up to the detector's noise) and
// motions by dynamic programming: a rest costs each frame its negative log-likelihood under a
// Gaussian about the rest's median position with the rest's own spread, capped so that outliers
// of tens of centimetres cost no more than a few sigmas; a motion costs what a rest spread over
// `max_rest_spread` would, per frame, and a penalty per motion. The noise is measured, not fixed:
// per track (the residuals to a running median, per principal direction: tracks jitter most
// along the camera ray) and per rest (a part may rest quietly, then wander by centimetres once
// the hand has moved in front of it). Rests whose poses
// lie closer than a carry's minimum displacement are one rest (drift, jumps, flips); a part moving
// with another (a tray) and keeping its place on it rides instead of being carried; frames where
// the part is not seen belong to the motion around them. Where the data cannot decide, the
// segmentation says so as a doubt over a frame range.
#include <string>
#include <vector>

#include <Eigen/Core>

#include "core/geometry/se3.h"
#include "perception/events/contact_detector.h"
#include "perception/tracking/pose_track.h"

namespace demoplan::perception {

struct TrackSegmentationOptions {
  double outlier_sigmas = 5.0;       // a rest frame costs at most this many of its rest's sigmas
  double max_rest_spread = 0.02;     // m: samples spread wider (one sigma) cost as much as moving
  double motion_penalty = 25.0;      // per motion
  int min_rest_frames = 5;           // seen frames a rest needs
  int max_unseen_end = 10;           // frames a part may go unseen at the end without a doubt
  double missing_cost = 0.01;        // per unseen frame in a rest: gaps go to the motion around them
  double min_noise = 0.001;          // m, floor of a track's measured noise per direction
  double min_carry_distance = 0.05;  // m: rests closer than this (and than below) are one rest
  double carry_sigmas = 6.0;         // ... or than this many sigmas along the displacement
  double min_carry_rotation = 0.5;   // rad: or turned at least this much (robust rest rotations)
  double ride_tolerance = 0.25;      // a rider's displacement may differ from its carrier's by
                                     // this fraction of the carrier's
  double min_confidence = 0.5;       // samples below are not used
};

enum class SegmentKind { Rest, Carry, Ride, Moving };

const char* segment_kind_name(SegmentKind kind);

// Frames [first, last] (inclusive) of one part. Rest: `pose` is its robust average (world).
// Carry: moved by the hand from the rest before to the rest after; its grasp frame is the last
// frame of the rest before, its release the first frame of the rest after. Ride: moved with
// `carrier` (a track row) keeping its place on it. Moving: a motion that is no carry (the part
// moves when the video starts or ends, or its carry was given up for another's).
struct TrackSegment {
  SegmentKind kind = SegmentKind::Rest;
  int first = 0, last = 0;
  int carrier = -1;
  Pose pose = Pose::Identity();
  double distance = 0.0;  // m, Carry and Ride: from the rest before to the rest after
};

// A track's noise as measured: the covariance of its translation residuals (m^2) and the
// median rotation residual (rad).
struct TrackNoise {
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Identity() * 1e-6;
  double sigma_max = 0.001;       // m, along the noisiest direction
  double sigma_min = 0.001;       // m, along the quietest
  double sigma_rotation = 0.0;    // rad
  int usable_frames = 0;
};

struct ObjectSegmentation {
  std::vector<TrackSegment> segments;  // in order, covering every frame of the video
  TrackNoise noise;
};

struct SegmentationDoubt {
  int object = -1;  // track row
  int first = 0, last = 0;
  std::string message;
};

struct TrackSegmentation {
  std::vector<ObjectSegmentation> objects;  // per track row
  std::vector<SegmentationDoubt> doubts;    // sorted by first frame

  // The carries of the planning parts, in time order: (track row, grasp frame, release frame)
  // as MotionIntervals, rides as transports, carries given up for another's as rejected, for
  // the code that reads a ContactAnalysis (the demonstration builder, smoothing, the UI).
  ContactAnalysis contacts(const PoseTracks& tracks) const;
};

TrackSegmentation segment_tracks(const PoseTracks& tracks, const TrackSegmentationOptions& options = {});

}  // namespace demoplan::perception
