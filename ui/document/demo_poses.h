#pragma once
// Where the demonstration puts every object at any frame, and which events share an object's
// rest pose: the rules the pose editor, the timeline and the 3D view agree on.
#include <vector>

#include "core/demo/demonstration.h"
#include "core/scene/scene.h"

namespace demoplan::ui {

// World pose of object `object` as stored at event `event`: a pose relative to a robot link
// (an object riding on the KMR's deck) is placed with the robot at `q`.
Pose world_pose_at_event(const Scene& scene, const Demonstration& demo, size_t event, int object,
                         const Eigen::VectorXd& q);

// Every object's world pose at `frame`: an object held between its grasp and its release moves
// from its grasp pose to its release pose (translation linear, rotation slerp); an object at
// rest keeps the pose of the last event at or before the frame (the first event's before it).
// Objects with no event at all: identity. The robot is at `q`.
PoseList demo_poses_at_frame(const Scene& scene, const Demonstration& demo, double frame,
                             const Eigen::VectorXd& q);

// The events at which `object` rests in the same place as at `event`: from its previous release
// (or the start) to its next grasp (or the end). An object at rest cannot move, so an edit of its
// pose applies to all of them. Contains `event` itself; only `event` when the object is held there.
std::vector<size_t> rest_events(const Demonstration& demo, size_t event, int object);

// The poses a new event at `frame` starts with: those of the last event at or before it (the
// first event's when none). Empty when the demonstration has no event.
ContactEvent new_event_at(const Demonstration& demo, int frame, int object, EventType type);

// Whether `object` is held (between a grasp and its release) at `frame`.
bool held_at_frame(const Demonstration& demo, int object, double frame);

}  // namespace demoplan::ui
