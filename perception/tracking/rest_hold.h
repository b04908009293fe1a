#pragma once
// A resting part held at its rest while another part moves (the one hand busy with that one),
// from a frame it was measured at rest in: the frames it is not measured in are kept aside and
// reported at the rest only when the hold is borne out, by its next measurement at that rest or
// by every part that moved meanwhile being seen at rest again (and not having moved together,
// as parts on a tray do: this one may have ridden along). Otherwise (measured elsewhere, the
// movers rode) none of them is: an inferred rest covers the whole time the part is not
// measured, or none of it (ModelTrackerOptions::hold_resting).
#include <Eigen/Core>
#include <vector>

#include "perception/tracking/color_histograms.h"

namespace demoplan::perception {

struct RestHold {
  bool on = false;
  std::vector<int> frames;                  // held, not reported yet
  std::vector<bool> movers;                 // the parts seen moving during the hold
  std::vector<Eigen::Vector3d> mover_from;  // where each was (world) when first seen moving in it
  // The part's colours as they show at the rest while nothing covers it there (its model may
  // have learnt a hand that was in front of it), taken up if the hold is borne out unmeasured.
  ColorHistograms colors;
  double contrast = 0.0;  // with those, in the last such frame

  // Holds part `self` in `frame` (starting a hold if none is on); `moving`: the parts moving now,
  // `rested_at`: where each part rested before this frame's move (world).
  void hold(int frame, size_t self, const std::vector<bool>& moving, const std::vector<Eigen::Vector3d>& rested_at);
  // Every part that moved during the hold seen again at rest: in the last frame, its image
  // still (within rest_px) over the last three frames it was seen in (`centres`). Until then
  // the hand may still be busy with it, out of sight or not. True when no hold is on.
  bool movers_at_rest(const std::vector<bool>& seen_last, const std::vector<std::vector<Eigen::Vector2d>>& centres,
                      double rest_px) const;
  // Two of the parts that moved during the hold went the same way (each farther than
  // `min_move`, their moves apart by less than `tolerance` of the longer); `now`: where each
  // part is (world).
  bool movers_rode(const std::vector<Eigen::Vector3d>& now, double min_move, double tolerance) const;
};

}  // namespace demoplan::perception
