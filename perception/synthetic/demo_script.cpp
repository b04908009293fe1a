#include "perception/synthetic/demo_script.h"

#include <algorithm>
#include <cmath>

#include "core/demo/benchmark_demonstration.h"
#include "core/error.h"
#include "core/geometry/planar_motion.h"
#include "core/geometry/se3.h"

namespace demoplan::perception {

namespace {

int scaled(int frame, double scale) { return static_cast<int>(std::lround(frame * scale)); }

// Eases in and out, but leaves rest with a visible velocity (a hand lifts decisively).
double carry_timing(double t) { return 0.5 * t + 0.5 * t * t * (3 - 2 * t); }

bool differs(const Pose& a, const Pose& b) {
  return (a.translation() - b.translation()).norm() > 0.01 ||
         Eigen::AngleAxisd(a.linear().transpose() * b.linear()).angle() > 0.05;
}

Eigen::AlignedBox3d world_box(const Eigen::AlignedBox3d& box, const Pose& pose) {
  Eigen::AlignedBox3d out;
  for (int k = 0; k < 8; ++k) out.extend(pose * box.corner(static_cast<Eigen::AlignedBox3d::CornerType>(k)));
  return out;
}

// Palm frame for holding a box (`bounds` in the frame at `pose`) from its far side as seen
// from the camera: palm normal (z) towards the part, fingers (x) down, forearm up.
Pose hand_on(const Eigen::AlignedBox3d& bounds, const Pose& pose, const Eigen::Vector3d& camera) {
  const Eigen::Vector3d c = pose * bounds.center();
  Eigen::Vector3d away = c - camera;
  away.z() = 0;
  away = away.norm() > 1e-6 ? away.normalized() : Eigen::Vector3d::UnitX();
  const Eigen::Vector3d h = bounds.sizes() / 2;
  double reach = 0;
  for (int i = 0; i < 3; ++i) reach += std::abs(away.dot(pose.linear().col(i))) * h[i];
  Pose H = Pose::Identity();
  const Eigen::Vector3d z = -away, x = -Eigen::Vector3d::UnitZ();
  H.linear().col(0) = x;
  H.linear().col(1) = z.cross(x);
  H.linear().col(2) = z;
  H.translation() = c + away * (reach + 0.015);
  return H;
}

// Where the hand waits before its first grasp: behind the part as the camera sees it, and up.
Pose raised_away(const Pose& H) {
  Pose out = H;
  out.translation() += -H.linear().col(2) * 0.25 + Eigen::Vector3d(0, 0, 0.3);
  return out;
}

// Where it waits after its last release: up and to the side, across the camera's line of sight
// (the palm's y is horizontal and square to it). Behind and up it hung between the camera and
// the part it had just put down, hiding that part to the end of the video.
Pose raised_aside(const Pose& H) {
  Pose out = H;
  out.translation() += H.linear().col(1) * 0.35 + Eigen::Vector3d(0, 0, 0.35);
  return out;
}

}  // namespace

Pose carry_pose(const Pose& A, const Pose& B, double t, double clearance) {
  const double s = carry_timing(std::clamp(t, 0.0, 1.0));
  const Eigen::Vector3d a = A.translation(), b = B.translation();
  const double top = std::max(a.z(), b.z()) + clearance;
  const Eigen::Vector3d a1(a.x(), a.y(), top), b1(b.x(), b.y(), top);
  const double u = 1 - s;
  Pose P = Pose::Identity();
  P.translation() = u * u * u * a + 3 * u * u * s * a1 + 3 * u * s * s * b1 + s * s * s * b;
  P.linear() = interpolate(A, B, s).linear();  // the path is lifted, the rotation is not
  return P;
}

Demonstration DemoScript::truth() const {
  Demonstration d;
  d.task = task;
  d.fps = fps;
  d.object_ids = object_ids;
  for (const auto& c : carries) {
    d.events.push_back({c.grasp, c.object, EventType::Grasp, 1.0, poses[c.grasp], {}});
    d.events.push_back({c.release, c.object, EventType::Release, 1.0, poses[c.release], {}});
  }
  std::stable_sort(d.events.begin(), d.events.end(), [](auto& a, auto& b) { return a.frame < b.frame; });
  return d;
}

DemoScript make_demo_script(const BenchmarkTask& task, const std::vector<Eigen::AlignedBox3d>& object_bounds,
                            double time_scale) {
  if (task.subgoal_poses.empty())
    throw InputError(task.file, "subgoal_objects_poses", "the task has no subgoal key poses to animate");
  if (!(time_scale > 0.05 && time_scale <= 4.0)) throw InputError(task.file, "time_scale", "must be in (0.05, 4]");
  const auto segments = contact_segments(task);
  const size_t n = task.planning_object_ids.size();
  const auto& sub = task.subgoal_poses;
  if (sub.front().size() != 2 * segments.size())
    throw InputError(task.file, "subgoal_objects_poses", "expected two subgoal columns per contact segment");

  DemoScript s;
  s.task = task.name();
  s.object_ids = task.planning_object_ids;
  s.bounds = object_bounds;
  for (const auto& seg : segments) {
    ScriptCarry c{seg.object, scaled(seg.first, time_scale), scaled(seg.last + 1, time_scale)};
    if (!s.carries.empty()) c.grasp = std::max(c.grasp, s.carries.back().release + 2);
    c.release = std::max(c.release, c.grasp + 4);
    s.carries.push_back(c);
  }
  s.frames = std::max(scaled(task.frames, time_scale), s.carries.empty() ? 1 : s.carries.back().release + 6);

  PoseList current(n);
  for (size_t o = 0; o < n; ++o) current[o] = sub[o][0];
  s.poses.assign(s.frames, current);
  s.tray.assign(s.frames, std::nullopt);

  auto hold = [&](int from) {  // everything at `current` from frame `from` on
    for (int f = std::max(0, from); f < s.frames; ++f) s.poses[f] = current;
  };
  for (size_t k = 0; k < s.carries.size(); ++k) {
    const ScriptCarry& c = s.carries[k];
    const Pose A = current[c.object], B = sub[c.object][2 * k + 1];
    for (int f = c.grasp + 1; f < c.release; ++f)
      s.poses[f][c.object] = carry_pose(A, B, double(f - c.grasp) / (c.release - c.grasp));
    current[c.object] = B;
    hold(c.release);
    if (k + 1 == s.carries.size()) break;
    // Parts that are not grasped but sit elsewhere before the next grasp rode on the tray.
    ScriptTransport t;
    std::vector<Eigen::Vector3d> from, to;
    for (size_t o = 0; o < n; ++o)
      if (differs(current[o], sub[o][2 * k + 2])) {
        t.objects.push_back(static_cast<int>(o));
        from.push_back(current[o].translation());
        to.push_back(sub[o][2 * k + 2].translation());
      }
    if (t.objects.empty()) continue;
    const int next_grasp = s.carries[k + 1].grasp;
    const int gap = next_grasp - c.release;
    // Only a real ride (far, with time for it) is animated; smaller differences between the
    // columns are inconsistencies of the key poses (waiter_0), and the parts stay put.
    double shift = 0;
    for (size_t i = 0; i < from.size(); ++i) shift += (to[i] - from[i]).norm() / static_cast<double>(from.size());
    if (shift < 0.25 || gap < 12) continue;
    t.start = c.release + std::max(4, gap / 3);
    t.end = std::max(t.start + 2, next_grasp - std::max(3, gap / 5));
    const PlanarMotion motion = fit_planar_motion(from, to);
    Eigen::AlignedBox3d footprint;
    for (int o : t.objects) footprint.extend(world_box(object_bounds[o], current[o]));
    Pose tray = Pose::Identity();
    tray.translation() << footprint.center().x(), footprint.center().y(), footprint.min().z() - 0.001;
    s.tray_size << footprint.sizes().x() + 0.08, footprint.sizes().y() + 0.08, 0.015;
    const PoseList before = current;
    for (int f = 0; f < s.frames; ++f) {
      const double u = std::clamp(double(f - t.start) / (t.end - t.start), 0.0, 1.0);
      const Pose M = motion.at(carry_timing(u));
      if (f >= c.release || !s.tray[f]) s.tray[f] = M * tray;
      if (f <= t.start) continue;
      for (int o : t.objects) s.poses[f][o] = M * before[o];
    }
    for (int o : t.objects) current[o] = motion.at(1.0) * before[o];
    s.transports.push_back(t);
  }
  return s;
}

DemoScript make_demo_script(const Demonstration& truth, const PoseList& start,
                            const std::vector<Eigen::AlignedBox3d>& object_bounds, int tail) {
  const size_t n = truth.object_ids.size();
  if (start.size() != n || object_bounds.size() != n)
    throw InputError(truth.task, "object_ids", "the start poses and part bounds must cover every part");
  DemoScript s;
  s.task = truth.task;
  s.fps = truth.fps;
  s.object_ids = truth.object_ids;
  s.bounds = object_bounds;
  std::vector<int> open(n, -1);  // the frame of each part's pending grasp
  for (const auto& e : truth.events) {
    if (e.object < 0 || static_cast<size_t>(e.object) >= n)
      throw InputError(truth.task, "events", "an event names an unknown part");
    int& g = open[e.object];
    if (e.type == EventType::Grasp) {
      if (g >= 0) throw InputError(truth.task, "events", "part " + truth.object_ids[e.object] + " is grasped twice");
      g = e.frame;
    } else {
      if (g < 0) throw InputError(truth.task, "events", "part " + truth.object_ids[e.object] + " is released unheld");
      s.carries.push_back({e.object, g, e.frame});
      g = -1;
    }
  }
  for (size_t o = 0; o < n; ++o)
    if (open[o] >= 0) throw InputError(truth.task, "events", "part " + truth.object_ids[o] + " is never released");
  std::sort(s.carries.begin(), s.carries.end(), [](auto& a, auto& b) { return a.grasp < b.grasp; });
  s.frames = (truth.events.empty() ? 0 : truth.events.back().frame) + std::max(1, tail);
  s.poses.assign(s.frames, start);
  s.tray.assign(s.frames, std::nullopt);
  // Every part rests where the last event before a frame put it; carried parts follow their
  // lifted path in between.
  PoseList current = start;
  size_t next_event = 0;
  for (int f = 0; f < s.frames; ++f) {
    while (next_event < truth.events.size() && truth.events[next_event].frame <= f) {
      const ContactEvent& e = truth.events[next_event++];
      if (e.type == EventType::Release) current[e.object] = e.poses[e.object];
    }
    s.poses[f] = current;
  }
  for (const auto& c : s.carries) {
    const Pose A = s.poses[c.grasp][c.object];
    const auto release = std::find_if(truth.events.begin(), truth.events.end(), [&](auto& e) {
      return e.frame == c.release && e.object == c.object && e.type == EventType::Release;
    });
    const Pose B = release->poses[c.object];
    for (int f = c.grasp + 1; f < c.release; ++f)
      s.poses[f][c.object] = carry_pose(A, B, double(f - c.grasp) / (c.release - c.grasp));
  }
  return s;
}

void add_hand(DemoScript& s, const Eigen::Vector3d& camera) {
  struct Attachment {
    int start, end, object;  // object -1: the tray
  };
  std::vector<Attachment> att;
  for (const auto& c : s.carries) att.push_back({c.grasp - 2, c.release + 2, c.object});
  for (const auto& t : s.transports) att.push_back({t.start - 2, t.end + 2, -1});
  std::sort(att.begin(), att.end(), [](auto& a, auto& b) { return a.start < b.start; });
  for (size_t k = 0; k < att.size(); ++k) {
    att[k].start = std::max(att[k].start, k ? att[k - 1].end + 2 : 0);
    att[k].end = std::min(std::max(att[k].end, att[k].start), s.frames - 1);
  }
  const Eigen::AlignedBox3d tray_box(Eigen::Vector3d(-s.tray_size.x() / 2, -s.tray_size.y() / 2, -s.tray_size.z()),
                                     Eigen::Vector3d(s.tray_size.x() / 2, s.tray_size.y() / 2, 0));
  auto carried = [&](const Attachment& a, int f) -> Pose {
    return a.object >= 0 ? s.poses[f][a.object] : *s.tray[f];
  };
  s.hand.assign(s.frames, Pose::Identity());
  if (att.empty()) {
    for (auto& h : s.hand) h.translation() = camera + Eigen::Vector3d(0, 0, 5);  // out of view
    return;
  }
  std::vector<Pose, Eigen::aligned_allocator<Pose>> first(att.size()), last(att.size());
  for (size_t k = 0; k < att.size(); ++k) {
    const Attachment& a = att[k];
    const Pose start_pose = carried(a, a.start);
    const Pose H = hand_on(a.object >= 0 ? s.bounds[a.object] : tray_box, start_pose, camera);
    const Pose rel = start_pose.inverse() * H;
    for (int f = a.start; f <= a.end; ++f) s.hand[f] = carried(a, f) * rel;
    first[k] = s.hand[a.start];
    last[k] = s.hand[a.end];
  }
  auto travel = [&](const Pose& A, const Pose& B, int f0, int f1) {
    for (int f = std::max(0, f0); f <= std::min(f1, s.frames - 1); ++f)
      s.hand[f] = carry_pose(A, B, f1 > f0 ? double(f - f0) / (f1 - f0) : 1.0, 0.08);
  };
  const Pose home_in = raised_away(first.front()), home_out = raised_aside(last.back());
  travel(home_in, home_in, 0, att.front().start - 24);
  travel(home_in, first.front(), att.front().start - 24, att.front().start);
  for (size_t k = 0; k + 1 < att.size(); ++k) travel(last[k], first[k + 1], att[k].end, att[k + 1].start);
  travel(last.back(), home_out, att.back().end, att.back().end + 24);
  travel(home_out, home_out, att.back().end + 24, s.frames - 1);
}

}  // namespace demoplan::perception
