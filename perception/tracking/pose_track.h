#pragma once
// Per-frame pose estimates of every tracked part: what the event detector reads and what the
// UI draws under the video.
#include <cstdint>
#include <string>
#include <vector>

#include "core/demo/benchmark_task.h"
#include "core/geometry/se3.h"

namespace demoplan::perception {

struct PoseSample {
  bool valid = false;
  Pose pose = Pose::Identity();  // world_T_object
  double confidence = 0.0;       // 0..1
  int markers = 0;               // markers it was computed from (0: another source)
  double reprojection_px = 0.0;
  bool ambiguous = false;        // the planar two-fold ambiguity was resolved from other frames
  // Expected standard deviation of the estimate (from the geometry of the points it was
  // computed from); 0 when unknown.
  double sigma_translation = 0.0;  // m, along the worst direction
  double sigma_rotation = 0.0;     // rad
  // Which markers it was computed from (bit id % 64 of each; 0: unknown or not from markers).
  // Estimates from the same markers share their error while the part rests; from other
  // markers they may differ by up to the expected precision above.
  std::uint64_t marker_set = 0;
};

// One part's estimate in one frame, as a tracker reports it.
struct PoseObservation {
  int object = -1;  // row in the tracks (the tracker's parts() order)
  PoseSample sample;
};

struct PoseTracks {
  double fps = 30.0;
  int frames = 0;
  std::vector<std::string> object_ids;
  std::vector<bool> planning;                  // per object: part of the plan (not a tray)
  std::vector<std::vector<PoseSample>> samples;  // [object][frame]

  int object_index(const std::string& id) const;
  void resize(int frames);
};

// Tracks of the raw per-frame estimates of a benchmark task (objects_poses), all valid.
PoseTracks tracks_from_benchmark(const BenchmarkTask& task, double fps = 30.0);

}  // namespace demoplan::perception
