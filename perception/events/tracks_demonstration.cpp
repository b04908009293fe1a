#include "perception/events/tracks_demonstration.h"

#include <algorithm>

#include "core/error.h"

namespace demoplan::perception {

std::vector<ContactSegment> carries_as_segments(const PoseTracks& tracks, const TrackSegmentation& segmentation) {
  // Track rows to planning indices (the tray is no planning part).
  std::vector<int> planning_index(tracks.object_ids.size(), -1);
  int next = 0;
  for (size_t i = 0; i < tracks.object_ids.size(); ++i)
    if (i < tracks.planning.size() && tracks.planning[i]) planning_index[i] = next++;
  std::vector<ContactSegment> out;
  for (const MotionInterval& m : segmentation.contacts(tracks).carries)
    if (planning_index[m.object] >= 0) out.push_back({planning_index[m.object], m.start, m.end - 1});
  std::sort(out.begin(), out.end(), [](auto& a, auto& b) { return a.first < b.first; });
  return out;
}

TracksDemonstration demonstration_from_tracks(const BenchmarkTask& task, const Scene& scene,
                                              const TrackSegmentationOptions& options) {
  TracksDemonstration out;
  out.tracks = tracks_from_benchmark(task);
  out.segmentation = segment_tracks(out.tracks, options);
  const auto segments = carries_as_segments(out.tracks, out.segmentation);
  if (segments.empty())
    throw InputError(task.file, "objects_poses",
                     "no part is carried in the pose tracks (every planning part rests over all " +
                         std::to_string(task.frames) + " frames, or moves no more than its noise)");
  out.demonstration = demonstration_from_segments(task, scene, segments);
  for (const SegmentationDoubt& d : out.segmentation.doubts) {
    const int o = out.demonstration.object_index(out.tracks.object_ids[d.object]);
    if (o >= 0) out.demonstration.doubts.push_back({o, d.first, d.last, d.message});
  }
  return out;
}

}  // namespace demoplan::perception
