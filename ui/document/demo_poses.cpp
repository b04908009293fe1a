#include "ui/document/demo_poses.h"

#include <algorithm>

#include "core/geometry/se3.h"

namespace demoplan::ui {

Pose world_pose_at_event(const Scene& scene, const Demonstration& demo, size_t event, int object,
                         const Eigen::VectorXd& q) {
  const ContactEvent& e = demo.events[event];
  if (object < 0 || static_cast<size_t>(object) >= e.poses.size()) return Pose::Identity();
  const std::string& frame = e.pose_frame(object);
  if (frame.empty()) return e.poses[object];
  const int link = scene.robot.model.link_index(frame);
  if (link < 0 || q.size() != scene.robot.model.nq) return e.poses[object];
  return link_pose(scene.robot.model, q, scene.robot.base, link) * e.poses[object];
}

bool held_at_frame(const Demonstration& demo, int object, double frame) {
  bool held = false;
  for (const auto& e : demo.events) {
    if (e.frame > frame) break;
    if (e.object == object) held = e.type == EventType::Grasp;
  }
  return held;
}

PoseList demo_poses_at_frame(const Scene& scene, const Demonstration& demo, double frame, const Eigen::VectorXd& q) {
  const size_t n = demo.object_ids.size();
  PoseList poses(n, Pose::Identity());
  if (demo.events.empty()) return poses;
  // The last event at or before the frame (the first event when the frame precedes them all).
  size_t last = 0;
  for (size_t i = 0; i < demo.events.size(); ++i)
    if (demo.events[i].frame <= frame) last = i;
  for (size_t o = 0; o < n; ++o) {
    const int obj = static_cast<int>(o);
    poses[o] = world_pose_at_event(scene, demo, last, obj, q);
    // Held: between a grasp of this object at or before the frame and its next release.
    int grasp = -1;
    for (size_t i = 0; i < demo.events.size() && demo.events[i].frame <= frame; ++i)
      if (demo.events[i].object == obj) grasp = demo.events[i].type == EventType::Grasp ? static_cast<int>(i) : -1;
    if (grasp < 0) continue;
    for (size_t i = grasp + 1; i < demo.events.size(); ++i) {
      const ContactEvent& e = demo.events[i];
      if (e.object != obj) continue;
      if (e.type != EventType::Release) break;
      const double f0 = demo.events[grasp].frame, f1 = e.frame;
      const double s = f1 > f0 ? std::clamp((frame - f0) / (f1 - f0), 0.0, 1.0) : 1.0;
      poses[o] = interpolate(world_pose_at_event(scene, demo, grasp, obj, q), world_pose_at_event(scene, demo, i, obj, q), s);
      break;
    }
  }
  return poses;
}

std::vector<size_t> rest_events(const Demonstration& demo, size_t event, int object) {
  // Label every event with the rest interval of `object` it belongs to (-1: held there).
  std::vector<int> label(demo.events.size(), -1);
  int interval = 0;
  bool held = false;
  for (size_t i = 0; i < demo.events.size(); ++i) {
    const ContactEvent& e = demo.events[i];
    if (e.object == object && e.type == EventType::Grasp) {
      label[i] = held ? -1 : interval;  // the pose it is picked up from
      held = true;
    } else if (e.object == object && e.type == EventType::Release) {
      ++interval;
      label[i] = interval;  // the pose it is put down at
      held = false;
    } else {
      label[i] = held ? -1 : interval;
    }
  }
  if (event >= demo.events.size()) return {};
  if (label[event] < 0) return {event};
  std::vector<size_t> out;
  for (size_t i = 0; i < demo.events.size(); ++i) {
    if (label[i] != label[event]) continue;
    // The same rest only when the pose is expressed in the same frame.
    if (demo.events[i].pose_frame(object) != demo.events[event].pose_frame(object)) continue;
    out.push_back(i);
  }
  return out;
}

ContactEvent new_event_at(const Demonstration& demo, int frame, int object, EventType type) {
  ContactEvent e;
  e.frame = frame;
  e.object = object;
  e.type = type;
  e.confidence = 1.0;
  if (demo.events.empty()) {
    e.poses.assign(demo.object_ids.size(), Pose::Identity());
    return e;
  }
  size_t source = 0;
  for (size_t i = 0; i < demo.events.size(); ++i)
    if (demo.events[i].frame <= frame) source = i;
  e.poses = demo.events[source].poses;
  e.pose_frames = demo.events[source].pose_frames;
  return e;
}

}  // namespace demoplan::ui
