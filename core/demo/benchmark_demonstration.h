#pragma once
// Demonstrations from the benchmark's task files: the contact labels give the events, the
// cleaned key poses (subgoals) or the raw per-frame video estimates give the object poses.
#include <string>
#include <vector>

#include "core/demo/benchmark_task.h"
#include "core/demo/demonstration.h"

namespace demoplan {

// A maximal run of frames in which the hand holds one object.
struct ContactSegment {
  int object = -1;  // index into planning_object_ids
  int first = 0, last = 0;  // inclusive frames
};
// Segments of the planning objects, sorted by first frame.
std::vector<ContactSegment> contact_segments(const BenchmarkTask& task);

// Events: a grasp at each segment's first frame, a release at the frame after its last. Poses:
// subgoal column 2k at the k-th grasp and 2k+1 at the k-th release. Throws InputError when the
// task has no subgoals or their count does not match the segments.
Demonstration demonstration_from_subgoals(const BenchmarkTask& task);

}  // namespace demoplan
