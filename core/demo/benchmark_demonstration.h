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
// subgoal column 2k at the k-th grasp and 2k+1 at the k-th release, all in the world. Throws
// InputError when the task has no subgoals or their count does not match the segments.
Demonstration demonstration_from_subgoals(const BenchmarkTask& task);

// The same events, with every object's pose decided per rest interval (from a release, or the
// start, to its next grasp, or the end) and placed on its support in `scene`:
//  - on furniture: the subgoal pose (subgoals), or the robust average of the raw frames of the
//    interval snapped onto the furniture surface (raw);
//  - on nothing the furniture offers while the robot has a surface of its own (waiter: the
//    demonstrator's tray, the KMR's deck): relative to the robot link carrying that surface,
//    at the object's offset from the tray centre, snapped onto the surface. That pose suits a
//    hand; place_on_deck() (core/placement/deck_placement.h), the next stage, moves it where the
//    robot's picks can be done.
// Throws InputError naming the event when an object rests on nothing.
enum class PoseSource { Subgoals, Raw };
Demonstration demonstration_from_benchmark(const BenchmarkTask& task, const Scene& scene, PoseSource source);

// The raw demonstration with events from `segments` (another source's carries, e.g. detected
// from the pose tracks) in place of the contact labels, which it does not read. Throws
// InputError naming the segment when one lies outside the task's objects or frames.
Demonstration demonstration_from_segments(const BenchmarkTask& task, const Scene& scene,
                                          const std::vector<ContactSegment>& segments);

// How far one demonstration's object poses lie from another's (same events), over every
// (event, object) pair whose pose is in the world in both.
struct PoseDeviation {
  int pairs = 0;
  double median_translation_mm = 0, max_translation_mm = 0;
  double median_rotation_deg = 0, max_rotation_deg = 0;
};
PoseDeviation pose_deviation(const Demonstration& a, const Demonstration& b);

}  // namespace demoplan
