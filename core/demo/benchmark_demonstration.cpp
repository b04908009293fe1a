#include "core/demo/benchmark_demonstration.h"

#include <algorithm>
#include <cmath>

#include "core/demo/rest_pose.h"
#include "core/error.h"
#include "core/scene/support.h"
#include "core/statistics.h"

namespace demoplan {

namespace {

Demonstration events_only(const BenchmarkTask& task, const std::vector<ContactSegment>& segments) {
  Demonstration d;
  d.task = task.name();
  d.object_ids = task.planning_object_ids;
  for (const auto& s : segments) {
    d.events.push_back({s.first, s.object, EventType::Grasp, 1.0, {}, {}});
    d.events.push_back({s.last + 1, s.object, EventType::Release, 1.0, {}, {}});
  }
  return d;
}

// An object at rest between two of its events (-1: the start or the end of the video).
struct RestInterval {
  int start_event = -1, end_event = -1;
  int first_frame = 0, last_frame = 0;
};

std::vector<RestInterval> rest_intervals(const Demonstration& d, int object, int frames) {
  std::vector<RestInterval> out{{-1, -1, 0, frames - 1}};
  for (size_t e = 0; e < d.events.size(); ++e) {
    if (d.events[e].object != object) continue;
    if (d.events[e].type == EventType::Grasp) {
      out.back().end_event = static_cast<int>(e);
      out.back().last_frame = d.events[e].frame - 1;
    } else {
      out.push_back({static_cast<int>(e), -1, d.events[e].frame, frames - 1});
    }
  }
  return out;
}

double yaw_of(const Pose& T) { return std::atan2(T(1, 0), T(0, 0)); }

// A pose in the frame of a tray lying on the floor: only its position in the plane and its
// yaw count (its raw height and tilt are estimation noise).
Pose relative_to_tray(const Pose& tray, const Pose& object) {
  Pose flat = Pose::Identity();
  flat.linear() = Eigen::AngleAxisd(yaw_of(tray), Eigen::Vector3d::UnitZ()).toRotationMatrix();
  flat.translation() << tray.translation().x(), tray.translation().y(), 0.0;
  return flat.inverse() * object;
}

// Poses of every object at every event of `d` (events set): subgoal columns or raw averages.
Demonstration place_objects(const BenchmarkTask& task, const Scene& scene, Demonstration d, bool subgoals);

class SupportAssigner {
public:
  SupportAssigner(const BenchmarkTask& task, const Scene& scene) : task_(task), scene_(scene) {
    for (const auto& s : support_polygons(scene))
      (s.robot_link >= 0 ? robot_ : furniture_).push_back(s);
    for (size_t i = 0; i < task.objects.size(); ++i)
      if (task.objects[i].id.rfind("TRAY", 0) == 0) tray_row_ = static_cast<int>(i);
  }

  // Decides where object o rests over a rest interval. `raw` are its per-frame video
  // estimates over the interval (with their frames); `cleaned` the subgoal pose, if any.
  // An object on the demonstrator's tray rests on the robot's deck, at its offset from the
  // tray centre; any other rests on furniture.
  std::pair<Pose, std::string> place(int o, const PoseList& raw, const std::vector<int>& frames,
                                     const Pose* cleaned, int event) const {
    const auto faces = object_contact_polygons(scene_.objects[o]);
    if (tray_row_ >= 0 && !robot_.empty()) {
      PoseList relative;
      for (size_t k = 0; k < raw.size(); ++k)
        relative.push_back(relative_to_tray(task_.raw_poses[tray_row_][frames[k]], raw[k]));
      const Pose on_tray = robust_static_pose(relative);
      if (on_tray.translation().head<2>().cwiseAbs().maxCoeff() < kTrayReach) return on_deck(o, faces, on_tray, event);
    }
    if (cleaned) return {*cleaned, ""};  // the subgoals already rest on their furniture
    const Pose world = robust_static_pose(raw);
    std::vector<std::vector<Eigen::Vector3d>> polys;
    for (const auto& s : furniture_) polys.push_back(s.vertices);
    // Raw estimates float, sink or overhang by centimetres (once by 35 cm in waiter_0): look
    // for the support further away and slide the object onto it.
    SnapOptions raw_tolerance;
    raw_tolerance.max_distance = 0.4;
    raw_tolerance.max_outside = 0.1;
    if (auto snapped = snap_to_support(faces, world, polys, raw_tolerance)) return {snapped->pose, ""};
    throw InputError(task_.file, "events[" + std::to_string(event) + "]",
                     scene_.objects[o].id + " rests on no support surface of the scene near (" +
                         std::to_string(world.translation().x()) + ", " + std::to_string(world.translation().y()) +
                         ", " + std::to_string(world.translation().z()) + ")");
  }

private:
  // Half the tray's side (0.15 m) plus a margin for the estimate's noise.
  static constexpr double kTrayReach = 0.22;

  std::pair<Pose, std::string> on_deck(int o, const std::vector<std::vector<Eigen::Vector3d>>& faces,
                                       const Pose& on_tray, int event) const {
    const SupportPolygon& deck = robot_.front();
    Eigen::Vector3d centre = Eigen::Vector3d::Zero();
    for (const auto& v : deck.vertices) centre += v;
    centre /= static_cast<double>(deck.vertices.size());
    Pose pose = on_tray;
    pose.translation().head<2>() += centre.head<2>();
    pose.translation().z() = centre.z() + 0.05;  // roughly above; the snap sets the height
    SnapOptions loose;
    loose.max_distance = 0.2;
    auto snapped = snap_to_support(faces, pose, {deck.vertices}, loose);
    if (!snapped)
      throw InputError(task_.file, "events[" + std::to_string(event) + "]",
                       scene_.objects[o].id + " on the tray does not fit on the robot's " + deck.name);
    return {snapped->pose, scene_.robot.model.links[deck.robot_link].name};
  }

  const BenchmarkTask& task_;
  const Scene& scene_;
  std::vector<SupportPolygon> furniture_, robot_;
  int tray_row_ = -1;
};

}  // namespace

std::vector<ContactSegment> contact_segments(const BenchmarkTask& task) {
  std::vector<ContactSegment> out;
  const auto rows = task.planning_rows();
  for (size_t o = 0; o < rows.size(); ++o) {
    const auto& c = task.contacts[rows[o]];
    for (int t = 0; t < static_cast<int>(c.size()); ++t) {
      if (!c[t] || (t > 0 && c[t - 1])) continue;
      int last = t;
      while (last + 1 < static_cast<int>(c.size()) && c[last + 1]) ++last;
      out.push_back({static_cast<int>(o), t, last});
    }
  }
  std::sort(out.begin(), out.end(), [](auto& a, auto& b) { return a.first < b.first; });
  return out;
}

Demonstration demonstration_from_subgoals(const BenchmarkTask& task) {
  if (task.subgoal_poses.empty())
    throw InputError(task.file, "subgoal_objects_poses", "the task has no subgoals (null)");
  Demonstration d = events_only(task, contact_segments(task));
  const size_t columns = task.subgoal_poses.front().size();
  if (columns != d.events.size())
    throw InputError(task.file, "subgoal_objects_poses",
                     std::to_string(columns) + " columns for " + std::to_string(d.events.size() / 2) +
                         " contact segments (expected two per segment)");
  for (size_t e = 0; e < d.events.size(); ++e)
    for (const auto& row : task.subgoal_poses) d.events[e].poses.push_back(row[e]);
  return d;
}

Demonstration demonstration_from_benchmark(const BenchmarkTask& task, const Scene& scene, PoseSource source) {
  if (source == PoseSource::Subgoals) return place_objects(task, scene, demonstration_from_subgoals(task), true);
  return demonstration_from_segments(task, scene, contact_segments(task));
}

Demonstration demonstration_from_segments(const BenchmarkTask& task, const Scene& scene,
                                          const std::vector<ContactSegment>& segments) {
  for (size_t k = 0; k < segments.size(); ++k) {
    const auto& s = segments[k];
    if (s.object < 0 || s.object >= static_cast<int>(task.planning_object_ids.size()) || s.first < 0 ||
        s.last < s.first || s.last >= task.frames)
      throw InputError(task.file, "segments[" + std::to_string(k) + "]",
                       "object " + std::to_string(s.object) + ", frames " + std::to_string(s.first) + "-" +
                           std::to_string(s.last) + " are outside the task's objects or its " +
                           std::to_string(task.frames) + " frames");
  }
  return place_objects(task, scene, events_only(task, segments), false);
}

namespace {

Demonstration place_objects(const BenchmarkTask& task, const Scene& scene, Demonstration d, bool subgoals) {
  const size_t n = d.object_ids.size();
  if (d.events.empty()) throw InputError(task.file, "contacts", "no object is ever held");
  for (auto& e : d.events) {
    e.poses.resize(n, Pose::Identity());
    e.pose_frames.assign(n, "");
  }
  const SupportAssigner assign(task, scene);
  const auto rows = task.planning_rows();
  for (size_t o = 0; o < n; ++o) {
    for (const RestInterval& r : rest_intervals(d, static_cast<int>(o), task.frames)) {
      // Frames well inside the rest: the hand may still touch the object at its ends.
      PoseList raw;
      std::vector<int> frames;
      const int margin = (r.last_frame - r.first_frame) > 6 ? 2 : 0;
      for (int f = r.first_frame + margin; f <= r.last_frame - margin; ++f) {
        raw.push_back(task.raw_poses[rows[o]][f]);
        frames.push_back(f);
      }
      if (raw.empty()) {
        const int f = std::clamp(r.first_frame, 0, task.frames - 1);
        raw.push_back(task.raw_poses[rows[o]][f]);
        frames.push_back(f);
      }
      // Subgoals: the first column before the first pick and the last after the last release
      // (the benchmark's start and goal); in between, the column at the end of the rest (the
      // pose the object is picked up from: waiter_0's columns drift while objects ride).
      const int last = static_cast<int>(d.events.size()) - 1;
      const int where = r.start_event < 0 ? 0 : r.end_event < 0 ? last : r.end_event;
      const Pose* cleaned = subgoals ? &d.events[where].poses[o] : nullptr;
      const auto [pose, frame] = assign.place(static_cast<int>(o), raw, frames, cleaned, where);
      // Every event during the rest, and the two that bound it, see the object there.
      const int from = std::max(r.start_event, 0);
      const int to = r.end_event >= 0 ? r.end_event : static_cast<int>(d.events.size()) - 1;
      for (int e = from; e <= to; ++e) {
        d.events[e].poses[o] = pose;
        d.events[e].pose_frames[o] = frame;
      }
    }
  }
  bool any_frame = false;
  for (const auto& e : d.events)
    for (const auto& f : e.pose_frames) any_frame |= !f.empty();
  if (!any_frame)
    for (auto& e : d.events) e.pose_frames.clear();
  return d;
}

}  // namespace

PoseDeviation pose_deviation(const Demonstration& a, const Demonstration& b) {
  std::vector<double> t, r;
  for (size_t e = 0; e < std::min(a.events.size(), b.events.size()); ++e)
    for (size_t o = 0; o < a.object_ids.size(); ++o) {
      // World poses only: deck poses come from the same raw track in both sources.
      if (!a.events[e].pose_frame(static_cast<int>(o)).empty() || !b.events[e].pose_frame(static_cast<int>(o)).empty())
        continue;
      const Pose d = a.events[e].poses[o].inverse() * b.events[e].poses[o];
      t.push_back((a.events[e].poses[o].translation() - b.events[e].poses[o].translation()).norm() * 1000);
      r.push_back(log3(d.linear()).norm() * 180 / M_PI);
    }
  PoseDeviation out;
  out.pairs = static_cast<int>(t.size());
  if (t.empty()) return out;
  out.median_translation_mm = median(t);
  out.max_translation_mm = *std::max_element(t.begin(), t.end());
  out.median_rotation_deg = median(r);
  out.max_rotation_deg = *std::max_element(r.begin(), r.end());
  return out;
}

}  // namespace demoplan
