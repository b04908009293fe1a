#pragma once
// A part's placed pose (its start, or where the operator placed it again) against its track,
// while the track has not carried it away. A placement made over a frame where something not
// modelled covers the part (the demonstrator's hand over it in the start frame) teaches the
// tracker the hand's colours, and its outline follows the forearm some centimetres off while the
// part has not moved (waiter_0's sugar box: 39 mm and 26 degrees). The frames after the hand
// has gone say which is right: the part's print at the placement matches them, at the tracked
// pose it does not. Borne out, the rest is reported at the placement; the tracking itself goes
// on from its own poses (ModelTrackerOptions::witness_placements).
#include "perception/tracking/appearance_error.h"

namespace demoplan::perception {

struct PlacementWitness {
  bool open = false;
  int from = 0;                           // the placement's frame
  Pose camera_T_placed = Pose::Identity();
  PrintShot clearest;                     // the frame its print at the placement differed least in
  double tracked_outliers = 2.0;          // in that frame, at the tracked pose
  int last_clear = -1;                    // the last frame its print at the placement was clear in

  void place(int frame, const Pose& camera_T_part);
  // What the print differed in, in `frame`, at the placement (`placed`) and at the tracked pose
  // (`tracked`), as fractions of the pixels each showed in; `clear`: at most that is clear.
  void look(int frame, const cv::Mat& image, const OcclusionMap& map, double placed, double tracked, double clear);
  // The placement clear in a frame where the tracked pose differed by `margin` more.
  bool borne_out(double clear, double margin) const;
};

}  // namespace demoplan::perception
