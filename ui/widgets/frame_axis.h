#pragma once
// The time axis the timeline and the panels under it share: frame 0 at the left of the plot
// area, the last frame at its right. One mapping, so a grasp in the timeline sits exactly above
// the same frame in the part tracks.
#include <algorithm>
#include <cmath>

namespace demoplan::ui {

struct FrameAxis {
  static constexpr int kGutter = 112;      // names and y ticks, left of the plot area
  static constexpr double kLeftPad = 8.0;  // room for a marker drawn at frame 0
  static constexpr double kRightPad = 14.0;

  double width = 0;  // of the widget
  int frames = 1;

  double left() const { return kGutter + kLeftPad; }
  double right() const { return width - kRightPad; }
  double toX(double frame) const { return left() + frame / double(std::max(2, frames) - 1) * (right() - left()); }
  int toFrame(double x) const {
    const int n = std::max(2, frames);
    const double f = (x - left()) / (right() - left()) * (n - 1);
    return std::clamp(int(std::lround(f)), 0, n - 1);
  }
};

}  // namespace demoplan::ui
