#pragma once
// A benchmark task's demonstration from its pose tracks alone (objects_poses): the events from
// segment_tracks, the rest poses as --from raw makes them (robust averages snapped onto their
// support, parts on the tray onto the robot's deck). Never reads the task's contact labels or
// subgoals. What `--from tracks` and the GUI's "Detect Events from Tracks" run.
#include <vector>

#include "core/demo/benchmark_demonstration.h"
#include "perception/events/track_segmentation.h"

namespace demoplan::perception {

// The carries of the planning parts as the benchmark's contact segments: grasp frame = first,
// release frame = last + 1; `object` indexes planning_object_ids.
std::vector<ContactSegment> carries_as_segments(const PoseTracks& tracks, const TrackSegmentation& segmentation);

struct TracksDemonstration {
  PoseTracks tracks;                 // tracks_from_benchmark(task)
  TrackSegmentation segmentation;
  Demonstration demonstration;       // with the segmentation's doubts
};

// Throws InputError (naming the task file) when no part is ever carried.
TracksDemonstration demonstration_from_tracks(const BenchmarkTask& task, const Scene& scene,
                                              const TrackSegmentationOptions& options = {});

}  // namespace demoplan::perception
