#include "core/validation/path_validator.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <mutex>
#include <set>
#include <sstream>
#include <thread>

#include "core/model/kinematics.h"
#include "core/parallel_for.h"
#include "core/path/path_interpolation.h"
#include "core/scene/collision_checker.h"
#include "core/scene/support.h"

namespace demoplan {

ValidationTask validation_task(const BenchmarkTask& task, const Scene& scene) {
  ValidationTask v;
  v.q_initial = scene.robot.initial_configuration;
  v.source = task.subgoal_poses.empty() ? "benchmark raw first/last frames" : "benchmark subgoals";
  size_t row = 0;
  for (size_t i = 0; i < task.objects.size(); ++i) {
    if (!task.objects[i].in_planning_model) continue;
    const PoseList& track = task.subgoal_poses.empty() ? task.raw_poses[i] : task.subgoal_poses[row];
    v.start_objects.push_back(track.front());
    v.goal_objects.push_back(track.back());
    ++row;
  }
  return v;
}

ValidationTask validation_task(const Demonstration& demo, const Scene& scene) {
  ValidationTask v;
  v.q_initial = scene.robot.initial_configuration;
  v.source = "demonstration";
  PoseVector links;
  forward_kinematics(scene.robot.model, v.q_initial, scene.robot.base, links);
  auto world = [&](const ContactEvent& e, int o) {
    const std::string& f = e.pose_frame(o);
    return f.empty() ? e.poses[o] : links[scene.robot.model.link_index(f)] * e.poses[o];
  };
  for (size_t o = 0; o < demo.object_ids.size(); ++o) {
    v.start_objects.push_back(world(demo.events.front(), static_cast<int>(o)));
    v.goal_objects.push_back(world(demo.events.back(), static_cast<int>(o)));
  }
  return v;
}

namespace {

bool near_identity(const Pose& a, const Pose& b, double tol) {
  const Pose d = b.inverse() * a;
  return (d.linear() - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff() <= tol &&
         d.translation().cwiseAbs().maxCoeff() <= tol;
}

std::string at(double t) {
  std::ostringstream s;
  s.precision(6);
  s << " at t = " << t;
  return s.str();
}

struct GraspPair {
  int object, handle;
  bool operator<(const GraspPair& o) const { return std::tie(object, handle) < std::tie(o.object, o.handle); }
};

// What the rules need of one sample.
struct SampleFacts {
  SceneState state;
  bool collides = false;
  CollisionPair hit;
  std::set<GraspPair> held;
  std::vector<int> support_link;    // per object: -2 not placed, -1 on the world, else the robot link
  PoseList support_frame;           // per object: its support link's world pose (identity for the world)
  int unplaced = -1;                // the first object neither grasped nor placed
};

}  // namespace

ValidationReport validate_path(const Scene& scene, const ValidationTask& task, const Path& path,
                               const ValidationOptions& o) {
  ValidationReport r;
  r.gripper_closes = static_cast<int>(std::count_if(path.waypoints.begin(), path.waypoints.end(),
                                                    [](const Waypoint& w) { return w.action == GripperAction::Grasp; }));
  auto fail = [&](const std::string& why, double t) {
    r.valid = false;
    r.message = why + (t >= 0 ? at(t) : "");
    r.failure_t = t;
    return r;
  };
  if (path.waypoints.empty()) return fail("the path has no waypoint", -1);
  const size_t n_objects = scene.objects.size();
  for (const auto& w : path.waypoints)
    if (w.q.size() != scene.robot.model.nq || w.objects.size() != n_objects)
      return fail("a waypoint does not match the scene (configuration or object count)", -1);
  const PathInterpolator interp(scene, path);
  const std::vector<double> ts = interp.sample_parameters(o.delta, o.max_joint_step);
  r.samples = ts.size();
  // The benchmark's compute_lengths on its own grid.
  const int n = static_cast<int>(std::ceil((1.0 + o.delta) / o.delta));
  SceneState a = interp.at(0.0);
  for (int k = 1; k < n; ++k) {
    const SceneState b = interp.at(std::min(1.0, k * o.delta));
    r.length.robot += (b.q - a.q).norm();
    double tr = 0.0, rot = 0.0;
    for (size_t i = 0; i < n_objects; ++i) {
      tr += (b.objects[i].translation() - a.objects[i].translation()).squaredNorm();
      const double angle = log3(a.objects[i].linear().transpose() * b.objects[i].linear()).norm();
      rot += angle * angle;
    }
    r.length.object_translation += std::sqrt(tr);
    r.length.object_rotation += std::sqrt(rot);
    a = b;
  }

  // 1 and 2: start and end.
  const SceneState first = interp.at(0.0), last = interp.at(1.0);
  for (size_t i = 0; i < n_objects; ++i) {
    if (!near_identity(first.objects[i], task.start_objects[i], o.error_identity))
      return fail(scene.objects[i].id + " does not start at its start pose (" + task.source + ")", 0.0);
    if (!near_identity(last.objects[i], task.goal_objects[i], o.error_identity))
      return fail(scene.objects[i].id + " does not end at its goal pose (" + task.source + ")", 1.0);
  }
  if ((first.q - task.q_initial).norm() > o.error_robot_distance)
    return fail("the robot does not start at its initial configuration", 0.0);
  if ((last.q - task.q_initial).norm() > o.error_robot_distance)
    return fail("the robot does not end at its initial configuration", 1.0);

  // Each sample's collisions, grasps and placements are independent of the others: found on
  // every core, in chunks taken in order, none after the first sample that fails on its own. The
  // rules between neighbouring samples are then judged in order, so the answer (the first
  // failure) is the same on any number of cores.
  const CollisionChecker checker(scene);
  const std::vector<SupportPolygon> supports = support_polygons(scene);
  const GraspFrame& gripper = scene.robot.gripper();
  std::vector<SampleFacts> facts(ts.size());
  std::atomic<size_t> first_bad{ts.size()};
  std::mutex pool_mutex;
  std::vector<CollisionData> pool;
  constexpr size_t kChunk = 64;
  const size_t chunks = (ts.size() + kChunk - 1) / kChunk;
  parallel_for(chunks, static_cast<int>(std::max(1u, std::thread::hardware_concurrency())), [&](size_t c) {
    if (c * kChunk > first_bad.load()) return;
    CollisionData data = [&] {
      std::lock_guard lock(pool_mutex);
      if (pool.empty()) return checker.make_data();
      CollisionData d = std::move(pool.back());
      pool.pop_back();
      return d;
    }();
    PoseVector links;
    for (size_t k = c * kChunk; k < std::min(ts.size(), (c + 1) * kChunk) && k <= first_bad.load(); ++k) {
      SampleFacts& f = facts[k];
      f.state = interp.at(ts[k]);
      f.support_link.assign(n_objects, -2);
      f.support_frame.assign(n_objects, Pose::Identity());
      // 3: collisions, every pair, no allowed contact.
      f.collides = checker.in_collision(f.state, data, {}, &f.hit);
      if (!f.collides) {
        forward_kinematics(scene.robot.model, f.state.q, scene.robot.base, links);
        const Pose g = links[scene.robot.gripper_link] * gripper.pose;
        for (size_t i = 0; i < n_objects && f.unplaced < 0; ++i) {
          const auto& handles = scene.objects[i].srdf.handles;
          bool grasped = false;
          for (size_t h = 0; h < handles.size(); ++h) {
            if (handles[h].clearance > gripper.clearance) continue;
            const Pose handle = f.state.objects[i] * handles[h].pose;
            if (log6(g.inverse() * handle).norm() < o.error_grasp) {
              f.held.insert({static_cast<int>(i), static_cast<int>(h)});
              grasped = true;
            }
          }
          const PlacementCheck placed = check_placement(scene, supports, links, static_cast<int>(i),
                                                         f.state.objects[i], {o.placement_lower, o.placement_upper});
          if (placed.placed) {
            const int l = supports[placed.support].robot_link;
            f.support_link[i] = l;
            if (l >= 0) f.support_frame[i] = links[l];
          }
          // 4: every object grasped or placed.
          if (!grasped && !placed.placed) f.unplaced = static_cast<int>(i);
        }
      }
      if (f.collides || f.unplaced >= 0) {
        size_t seen = first_bad.load();
        while (k < seen && !first_bad.compare_exchange_weak(seen, k)) {
        }
        break;
      }
    }
    std::lock_guard lock(pool_mutex);
    pool.push_back(std::move(data));
  });

  auto grasped_in = [](const std::set<GraspPair>& held, size_t i) {
    return std::any_of(held.begin(), held.end(), [&](auto& p) { return p.object == static_cast<int>(i); });
  };
  for (size_t k = 0; k < ts.size() && k <= first_bad.load(); ++k) {
    const SampleFacts& f = facts[k];
    const double t = ts[k];
    if (f.collides) return fail("collision between " + f.hit.first + " and " + f.hit.second, t);
    if (f.unplaced >= 0) return fail(scene.objects[f.unplaced].id + " is neither grasped nor placed", t);
    if (k == 0) continue;
    const SampleFacts& prev = facts[k - 1];
    // 5: a placed object does not move on its support (the benchmark's intended rule; its code
    // applies it to the mirrored object, see docs/validation.md), compared in its support's frame.
    for (size_t i = 0; i < n_objects; ++i) {
      if (grasped_in(f.held, i) || grasped_in(prev.held, i) || f.support_link[i] == -2 ||
          f.support_link[i] != prev.support_link[i])
        continue;
      const Pose now = f.support_frame[i].inverse() * f.state.objects[i];
      const Pose before = prev.support_frame[i].inverse() * prev.state.objects[i];
      if (!near_identity(now, before, o.error_identity)) return fail(scene.objects[i].id + " moves while placed", t);
    }
    // compute_n_grasps: (gripper, handle) pairs new since the previous sample.
    for (const auto& p : f.held)
      if (!prev.held.count(p)) {
        ++r.grasps;
        r.counted_grasps.push_back({t, scene.objects[p.object].id, scene.objects[p.object].srdf.handles[p.handle].name});
      }
  }
  if (!interp.uncarried().empty()) {
    const auto [seg, obj] = interp.uncarried().front();
    return fail(scene.objects[obj].id + " moves without being carried between waypoints " + std::to_string(seg) +
                    " and " + std::to_string(seg + 1),
                interp.waypoint_parameter(seg));
  }
  r.valid = true;
  r.message = "ok";
  return r;
}

std::string describe_grasps(int grasps, int gripper_closes) {
  const std::string counted = std::to_string(grasps) + (grasps == 1 ? " grasp" : " grasps");
  if (grasps == gripper_closes) return counted;
  return counted + " as the benchmark counts them, " + std::to_string(gripper_closes) +
         (gripper_closes == 1 ? " gripper close" : " gripper closes");
}

}  // namespace demoplan
