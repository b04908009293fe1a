#pragma once
// Hand-contact detections (100DOH) fused with the pose-based events. A hand in contact with a
// portable object touches the part whose projected box overlaps that object's box best (a part
// not seen for a while is placed where it was last seen, and then the nearest box counts);
// runs of such frames per part are its contacts. A contact run that overlaps a carry of the
// same part sets the carry's grasp (first contact frame) and release (frame after the last)
// when they lie within `max_shift` frames of the pose-based ones; several runs within one
// carry split it (the hand put the part down and took it again where the camera could not
// see it); a run on a part that was never seen moving (hidden while carried) adds a carry of
// its own when no other carry overlaps it.
#include <vector>

#include <Eigen/Geometry>

#include "perception/camera/camera_model.h"
#include "perception/events/contact_detector.h"
#include "perception/importers/hand_detections.h"
#include "perception/tracking/pose_track.h"

namespace demoplan::perception {

struct HandContactRun {
  int object = -1;  // track row
  int first = 0, last = 0;  // frames in contact, inclusive
};

struct HandFusionOptions {
  double min_overlap = 0.2;  // intersection over union of the boxes
  int max_gap = 3;           // frames without contact inside one run
  int min_length = 3;        // frames
  int max_shift = 6;         // frames between a hand event and the pose event it replaces
};

// `part_bounds`: each track row's extent in its frame.
std::vector<HandContactRun> hand_contact_runs(const std::vector<HandFrame>& hands, const PoseTracks& tracks,
                                              const std::vector<Eigen::AlignedBox3d>& part_bounds, const Camera& camera,
                                              const HandFusionOptions& options = {});

void fuse_hand_contacts(ContactAnalysis& contacts, const std::vector<HandContactRun>& runs, const PoseTracks& tracks,
                        const HandFusionOptions& options = {});

}  // namespace demoplan::perception
