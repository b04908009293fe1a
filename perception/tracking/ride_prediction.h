#pragma once
// A part not measured at its rest (held there, or lost from there) while parts that rested on
// the same support move away together as one rigid body (a tray or a board carried with them on
// it) most likely rode along: its pose is predicted as the rigid motion in the horizontal plane
// that takes their rests to where they are now, applied to its own rest, and the tracker looks
// for it there, every frame while they move and after they stop, until it is found at rest or
// they part (ModelTrackerOptions::ride_prediction).
#include <optional>
#include <vector>

#include "core/geometry/se3.h"

namespace demoplan::perception {

// One part as the ride's detection sees it (world, its model's centre).
struct RidePart {
  std::optional<Eigen::Vector3d> rest;  // where it was last measured at rest
  double rest_bottom = 0.0;             // the height of its lowest point there
  int left_rest = -1;                   // the frame that rest broke in (-1: not since)
  bool tracked = false;                 // measured in this frame or the last
  Eigen::Vector3d now = Eigen::Vector3d::Zero();  // its estimate
};

struct RideRules {
  double min_move = 0.05;           // m, each rider from its rest
  double tolerance = 0.03;          // m, left by the rigid fit,
  double tolerance_fraction = 0.1;  // plus this fraction of the longest move
  double height = 0.03;             // m: rests on the same support: their lowest points this close,
  double radii = 4.0;               // or their centres within this many of the part's radius
  int start_frames = 3;             // the riders left their rests within this many frames of each other
};

// The fit of riders' moves from their rests to where they are now, and whether it is one rigid
// body's (what it leaves within the rules' tolerance).
struct GroupFit {
  Pose motion = Pose::Identity();
  bool rigid = false;
};

// The parts another part rode with, from their rests.
class Ride {
public:
  // The largest group (at least two) of parts other than `self` that are tracked, left their
  // rests together and moved as one rigid body farther than the rules' min_move, one of them
  // from a rest on the same support as `self`'s (at `rest`, lowest point at `bottom`, of radius
  // `radius`); none: no ride. (One part alone is no ride: it is carried as often.)
  static std::optional<Ride> detect(size_t self, const Eigen::Vector3d& rest, double bottom, double radius,
                                    const std::vector<RidePart>& parts, const RideRules& rules);
  // The motion from the riders' rests to where they are now, if at least two of them are
  // tracked and they still move as one (else none: they parted, or cannot tell).
  std::optional<Pose> motion(const std::vector<RidePart>& parts, const RideRules& rules) const;
  // Whether the riders now move apart: two of them tracked and no longer one rigid body, or one
  // of them came to rest and left it again since.
  bool parted(const std::vector<RidePart>& parts, const RideRules& rules) const;

  const std::vector<size_t>& riders() const { return riders_; }

private:
  // Whether a rider came to rest and left it again since (it moves on its own then).
  bool left_again(const std::vector<RidePart>& parts) const;
  // The fit of the riders tracked now (none: fewer than two of them).
  std::optional<GroupFit> fit_tracked(const std::vector<RidePart>& parts, const RideRules& rules) const;

  std::vector<size_t> riders_;
  std::vector<Eigen::Vector3d> from_;  // their rests when the ride was seen,
  std::vector<int> left_;              // and the frames they left them in
};

}  // namespace demoplan::perception
