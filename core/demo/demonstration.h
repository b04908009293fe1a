#pragma once
// What the video shows: when the hand grasps and releases which object, and where every
// object is at those moments (Sec. III-A of the paper). Editable by the operator.
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "core/scene/scene.h"

namespace demoplan {

enum class EventType { Grasp, Release };

struct ContactEvent {
  int frame = 0;         // video frame at which the contact state changes
  int object = -1;       // index into Demonstration::object_ids
  EventType type = EventType::Grasp;
  double confidence = 1.0;  // 0..1; 1 for edited or ground-truth events
  PoseList poses;        // pose of every object at this event, in its frame (below)
  // Per object: "" when the pose is in the world, else the robot link the object rests on and
  // travels with (the KMR's deck); the pose is then relative to that link. Empty: all world.
  std::vector<std::string> pose_frames;

  const std::string& pose_frame(int object) const {
    static const std::string world;
    return pose_frames.empty() ? world : pose_frames[object];
  }
};

// Something the event detection could not decide, over a frame range of one object, for the
// operator to check on the timeline (a rest seen at two places with no carry between, a carry
// that ends nowhere). A doubt does not stop planning; the operator dismisses it by deleting it.
struct DetectionDoubt {
  int object = -1;  // index into Demonstration::object_ids
  int first_frame = 0, last_frame = 0;  // inclusive
  std::string message;
};

struct Demonstration {
  std::string task;  // the scene it refers to, e.g. benchmark task "shelf_1"
  double fps = 30.0;
  std::vector<std::string> object_ids;
  std::vector<ContactEvent> events;  // ordered by frame
  std::vector<DetectionDoubt> doubts;  // from event detection, ordered by first frame

  int object_index(const std::string& id) const;  // -1 when absent
  double time_s(int frame) const { return frame / fps; }
};

// A rule the demonstration breaks; `event` is the index of the offending event (-1: global).
struct DemonstrationIssue {
  int event = -1;
  std::string message;
};

// The rules: at least one event; events ordered by frame; per object, grasps and releases
// alternate starting with a grasp; at most one object held at a time (single arm); every
// event has one finite pose with an orthonormal rotation per object.
std::vector<DemonstrationIssue> validate(const Demonstration& demo);

// Edits keep the events ordered by frame. They do not validate: the UI shows the issues live.
size_t insert_event(Demonstration& demo, ContactEvent event);  // returns its index
void remove_event(Demonstration& demo, size_t index);
size_t move_event(Demonstration& demo, size_t index, int frame);  // returns the new index
void set_object_pose(Demonstration& demo, size_t event, int object, const Pose& pose);

// JSON: {"format": "demoplan-demonstration", "version": 1, ...}; poses are 4x4 row-major
// world transforms in metres. Saving is atomic. Loading throws InputError.
void save_demonstration(const std::string& path, const Demonstration& demo);
Demonstration load_demonstration(const std::string& path);
// The same JSON as a value, to embed in another file (a project). `source` names the file (and
// the field, e.g. "project.json: demonstration") in errors.
nlohmann::json demonstration_to_json(const Demonstration& demo);
Demonstration demonstration_from_json(const nlohmann::json& json, const std::string& source);

}  // namespace demoplan
