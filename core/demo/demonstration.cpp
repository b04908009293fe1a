#include "core/demo/demonstration.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "core/io/json_file.h"

namespace demoplan {

namespace {
constexpr const char* kFormat = "demoplan-demonstration";
constexpr int kVersion = 1;

const char* type_name(EventType t) { return t == EventType::Grasp ? "grasp" : "release"; }

std::string describe(const Demonstration& d, size_t i) {
  const auto& e = d.events[i];
  const std::string obj = e.object >= 0 && e.object < static_cast<int>(d.object_ids.size())
                              ? d.object_ids[e.object]
                              : "object #" + std::to_string(e.object);
  return std::string(type_name(e.type)) + " of " + obj + " at frame " + std::to_string(e.frame);
}
}  // namespace

int Demonstration::object_index(const std::string& id) const {
  auto it = std::find(object_ids.begin(), object_ids.end(), id);
  return it == object_ids.end() ? -1 : static_cast<int>(it - object_ids.begin());
}

std::vector<DemonstrationIssue> validate(const Demonstration& d) {
  std::vector<DemonstrationIssue> issues;
  if (d.object_ids.empty()) issues.push_back({-1, "the demonstration names no object"});
  if (d.events.empty()) {
    issues.push_back({-1, "the demonstration has no grasp or release event"});
    return issues;
  }
  const int n = static_cast<int>(d.object_ids.size());
  std::vector<bool> held(n, false);
  int holding = -1;
  for (size_t i = 0; i < d.events.size(); ++i) {
    const auto& e = d.events[i];
    const int idx = static_cast<int>(i);
    if (i > 0 && e.frame < d.events[i - 1].frame)
      issues.push_back({idx, describe(d, i) + " comes before the previous event's frame " +
                                 std::to_string(d.events[i - 1].frame)});
    if (e.object < 0 || e.object >= n) {
      issues.push_back({idx, "event " + std::to_string(i) + " refers to an unknown object"});
      continue;
    }
    if (e.type == EventType::Grasp) {
      if (held[e.object]) issues.push_back({idx, describe(d, i) + ": the object is already held"});
      else if (holding >= 0)
        issues.push_back({idx, describe(d, i) + ": " + d.object_ids[holding] +
                                   " is still held (one object at a time)"});
      held[e.object] = true;
      holding = e.object;
    } else {
      if (!held[e.object]) issues.push_back({idx, describe(d, i) + ": release without a grasp"});
      held[e.object] = false;
      if (holding == e.object) holding = -1;
    }
    if (e.poses.size() != static_cast<size_t>(n)) {
      issues.push_back({idx, describe(d, i) + ": has " + std::to_string(e.poses.size()) +
                                 " object poses, expected " + std::to_string(n)});
      continue;
    }
    for (int o = 0; o < n; ++o) {
      const Pose& T = e.poses[o];
      if (!T.matrix().allFinite())
        issues.push_back({idx, describe(d, i) + ": pose of " + d.object_ids[o] + " is not finite"});
      else if (!is_rotation(T.linear(), 1e-5))
        issues.push_back({idx, describe(d, i) + ": rotation of " + d.object_ids[o] + " is not orthonormal"});
    }
    if (!e.pose_frames.empty() && e.pose_frames.size() != static_cast<size_t>(n))
      issues.push_back({idx, describe(d, i) + ": has " + std::to_string(e.pose_frames.size()) +
                                 " pose frames, expected " + std::to_string(n)});
    if (!(e.confidence >= 0.0 && e.confidence <= 1.0))
      issues.push_back({idx, describe(d, i) + ": confidence must be within [0, 1]"});
  }
  for (int o = 0; o < n; ++o)
    if (held[o]) issues.push_back({-1, d.object_ids[o] + " is grasped but never released"});
  return issues;
}

size_t insert_event(Demonstration& d, ContactEvent e) {
  // After every event at the same or an earlier frame: a new event goes last among equals.
  auto it = std::upper_bound(d.events.begin(), d.events.end(), e.frame,
                             [](int f, const ContactEvent& x) { return f < x.frame; });
  const auto index = it - d.events.begin();  // before insert() may reallocate
  d.events.insert(it, std::move(e));
  return static_cast<size_t>(index);
}

void remove_event(Demonstration& d, size_t index) {
  if (index >= d.events.size()) throw std::out_of_range("remove_event: no event " + std::to_string(index));
  d.events.erase(d.events.begin() + static_cast<long>(index));
}

size_t move_event(Demonstration& d, size_t index, int frame) {
  if (index >= d.events.size()) throw std::out_of_range("move_event: no event " + std::to_string(index));
  ContactEvent e = std::move(d.events[index]);
  d.events.erase(d.events.begin() + static_cast<long>(index));
  e.frame = frame;
  return insert_event(d, std::move(e));
}

void set_object_pose(Demonstration& d, size_t event, int object, const Pose& pose) {
  if (event >= d.events.size()) throw std::out_of_range("set_object_pose: no event " + std::to_string(event));
  auto& poses = d.events[event].poses;
  if (object < 0 || static_cast<size_t>(object) >= poses.size())
    throw std::out_of_range("set_object_pose: no object " + std::to_string(object));
  poses[object] = pose;
}

void save_demonstration(const std::string& path, const Demonstration& d) {
  write_json_file_atomic(path, demonstration_to_json(d));
}

Json demonstration_to_json(const Demonstration& d) {
  Json j{{"format", kFormat},
         {"version", kVersion},
         {"pose_convention", "4x4 row-major pose of the object frame, metres, in the world or, where "
                             "'pose_frames' names a robot link, relative to that link"},
         {"task", d.task},
         {"fps", d.fps},
         {"objects", d.object_ids}};
  Json events = Json::array();
  for (const auto& e : d.events) {
    Json poses = Json::object(), frames = Json::object();
    for (size_t o = 0; o < e.poses.size() && o < d.object_ids.size(); ++o) {
      poses[d.object_ids[o]] = pose_matrix_json(e.poses[o]);
      if (o < e.pose_frames.size() && !e.pose_frames[o].empty()) frames[d.object_ids[o]] = e.pose_frames[o];
    }
    Json ev{{"frame", e.frame},
            {"object", e.object >= 0 && e.object < static_cast<int>(d.object_ids.size()) ? d.object_ids[e.object] : ""},
            {"type", type_name(e.type)},
            {"confidence", e.confidence},
            {"poses", poses}};
    if (!frames.empty()) ev["pose_frames"] = frames;
    events.push_back(std::move(ev));
  }
  j["events"] = events;
  if (!d.doubts.empty()) {
    Json doubts = Json::array();
    for (const auto& x : d.doubts)
      doubts.push_back({{"object", x.object >= 0 && x.object < static_cast<int>(d.object_ids.size()) ? d.object_ids[x.object] : ""},
                        {"first_frame", x.first_frame},
                        {"last_frame", x.last_frame},
                        {"message", x.message}});
    j["doubts"] = doubts;
  }
  return j;
}

Demonstration load_demonstration(const std::string& path) {
  return demonstration_from_json(read_json_file(path), path);
}

Demonstration demonstration_from_json(const Json& json, const std::string& path) {
  const JsonField root(json, path);
  check_format(root, kFormat, kVersion);
  Demonstration d;
  d.task = root["task"].string();
  d.fps = root["fps"].number();
  if (d.fps <= 0) root["fps"].fail("must be > 0");
  const JsonField objects = root["objects"];
  for (size_t i = 0; i < objects.size(); ++i) d.object_ids.push_back(objects[i].string());
  const JsonField events = root["events"];
  for (size_t i = 0; i < events.size(); ++i) {
    const JsonField e = events[i];
    ContactEvent ev;
    ev.frame = e["frame"].integer();
    if (ev.frame < 0) e["frame"].fail("must be >= 0");
    const std::string obj = e["object"].string();
    ev.object = d.object_index(obj);
    if (ev.object < 0) e["object"].fail("'" + obj + "' is not in objects");
    const std::string type = e["type"].string();
    if (type != "grasp" && type != "release") e["type"].fail("must be 'grasp' or 'release'");
    ev.type = type == "grasp" ? EventType::Grasp : EventType::Release;
    ev.confidence = e.has("confidence") ? e["confidence"].number() : 1.0;
    const JsonField poses = e["poses"];
    for (const auto& id : d.object_ids) ev.poses.push_back(poses[id].pose());
    if (e.has("pose_frames")) {
      const JsonField frames = e["pose_frames"];
      for (const auto& [id, _] : frames.value().items())
        if (d.object_index(id) < 0) frames[id].fail("'" + id + "' is not in objects");
      for (const auto& id : d.object_ids) ev.pose_frames.push_back(frames.has(id) ? frames[id].string() : "");
    }
    d.events.push_back(std::move(ev));
  }
  if (root.has("doubts")) {
    const JsonField doubts = root["doubts"];
    for (size_t i = 0; i < doubts.size(); ++i) {
      const JsonField x = doubts[i];
      DetectionDoubt doubt;
      const std::string obj = x["object"].string();
      doubt.object = d.object_index(obj);
      if (doubt.object < 0) x["object"].fail("'" + obj + "' is not in objects");
      doubt.first_frame = x["first_frame"].integer();
      doubt.last_frame = x["last_frame"].integer();
      if (doubt.first_frame < 0 || doubt.last_frame < doubt.first_frame)
        x["last_frame"].fail("the frames must satisfy 0 <= first_frame <= last_frame");
      doubt.message = x["message"].string();
      d.doubts.push_back(std::move(doubt));
    }
  }
  return d;
}

}  // namespace demoplan
