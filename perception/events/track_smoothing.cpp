#include "perception/events/track_smoothing.h"

#include <algorithm>

#include "perception/events/demonstration_builder.h"
#include "perception/tracking/pose_average.h"

namespace demoplan::perception {

PoseTracks smooth_tracks(const PoseTracks& raw, const ContactAnalysis& contacts, const ContactDetectorOptions& options,
                         int half_window) {
  PoseTracks out = raw;
  const int frames = raw.frames;
  for (size_t k = 0; k < raw.object_ids.size(); ++k) {
    const auto& in = raw.samples[k];
    auto& s = out.samples[k];
    for (auto& x : s) x = PoseSample{};
    const auto motions = contacts.motions_of(static_cast<int>(k));
    // Rests: one pose each.
    int first = 0;
    for (size_t m = 0; m <= motions.size(); ++m) {
      const int last = m < motions.size() ? motions[m].start : frames - 1;
      if (const auto pose = rest_pose(in, first, last, options)) {
        double conf = 0;
        int n = 0;
        for (int f = first; f <= last; ++f)
          if (in[f].valid) conf += in[f].confidence, ++n;
        for (int f = first; f <= last; ++f) {
          s[f].valid = true;
          s[f].pose = *pose;
          s[f].confidence = conf / std::max(1, n);
          s[f].markers = in[f].markers;
        }
      }
      if (m < motions.size()) first = motions[m].end;
    }
    // Motions: centred averages inside, anchored at the rests at both ends.
    for (const auto& m : motions) {
      std::vector<int> known;  // frames in [start, end] with a pose to average or interpolate from
      auto pose_at = [&](int f) -> const Pose& { return (f == m.start || f == m.end) && s[f].valid ? s[f].pose : in[f].pose; };
      for (int f = m.start; f <= m.end; ++f)
        if (((f == m.start || f == m.end) && s[f].valid) || (f > m.start && f < m.end && in[f].valid)) known.push_back(f);
      if (known.empty()) continue;
      for (int f = m.start + 1; f < m.end; ++f) {
        PoseList window;
        for (int g = std::max(m.start, f - half_window); g <= std::min(m.end, f + half_window); ++g)
          if (std::binary_search(known.begin(), known.end(), g)) window.push_back(pose_at(g));
        PoseSample& x = s[f];
        if (!window.empty() && in[f].valid) {
          x.pose = mean_pose(window);
        } else {
          auto after = std::lower_bound(known.begin(), known.end(), f);
          if (after == known.end() || after == known.begin()) continue;
          const int a = *(after - 1), b = *after;
          x.pose = interpolate(pose_at(a), pose_at(b), double(f - a) / (b - a));
        }
        x.valid = true;
        x.confidence = in[f].valid ? in[f].confidence : 0.5;
        x.markers = in[f].markers;
      }
    }
  }
  return out;
}

}  // namespace demoplan::perception
