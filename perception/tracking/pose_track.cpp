#include "perception/tracking/pose_track.h"

#include <algorithm>

#include "core/demo/benchmark_task.h"

namespace demoplan::perception {

int PoseTracks::object_index(const std::string& id) const {
  auto it = std::find(object_ids.begin(), object_ids.end(), id);
  return it == object_ids.end() ? -1 : static_cast<int>(it - object_ids.begin());
}

void PoseTracks::resize(int n) {
  frames = n;
  samples.resize(object_ids.size());
  for (auto& s : samples) s.resize(n);
}

PoseTracks tracks_from_benchmark(const BenchmarkTask& task, double fps) {
  PoseTracks t;
  t.fps = fps;
  for (const auto& o : task.objects) {
    t.object_ids.push_back(o.id);
    t.planning.push_back(o.in_planning_model);
  }
  t.resize(task.frames);
  for (size_t o = 0; o < task.objects.size(); ++o)
    for (int f = 0; f < task.frames && f < static_cast<int>(task.raw_poses[o].size()); ++f) {
      PoseSample& s = t.samples[o][f];
      s.valid = true;
      s.pose = task.raw_poses[o][f];
      s.confidence = 1.0;
    }
  return t;
}

}  // namespace demoplan::perception
