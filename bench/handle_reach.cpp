// Which of the YCB-V parts' hand-made SRDF handles the Panda's gripper can reach in the shelf_1
// scene, and how many of those a generated handle matches (issue 15's target: "at least one
// generated handle within 1 cm and 15 degrees of each of its SRDF handles that the gripper can
// reach in the shelf_1 scene"). A measurement, not a benchmark: it prints counts.
//
// Reachable, as measured here (deterministic: fixed seeds, fixed grid):
//   - scenes: build_benchmark_scene(shelf_1, panda, pose) for every published pose (0-4);
//   - the part replaces one of shelf_1's two parts (YCBV_02 or YCBV_05; the other stays at its
//     start pose, an obstacle) where that part rests on the table in the task's subgoal poses:
//     YCBV_02 at its start (0.197, 0.436), YCBV_05 at its goal (0.575, 0.137) (it starts on the
//     shelf's top; --on shelf takes the positions on the shelf instead). It stands on one of its
//     --placements stablest resting placements (core/part resting_placements on the mesh's convex
//     hull, centre of mass of the closed mesh), that face's centroid at the replaced part's
//     (x, y), 1 mm above the support polygon under it (the table top), turned by one of --yaws
//     yaws k * 360 / yaws degrees about the vertical; a resting pose where the part touches
//     anything but the robot (at its initial configuration) is skipped;
//   - per (pose, replaced part, placement, yaw): a one-pick Demonstration (demonstration_from_picks)
//     moving the part from there to the same pose 2 cm further along world +y, its constraint
//     graph with the part's SRDF handles (those with clearance above the gripper's opening get no
//     grasp state and are never reachable), and assess_picks with --samples samples per
//     transition (seed fixed per configuration);
//   - a handle is "pick-reachable" when, for some configuration, assess_picks lists it in
//     PickFeasibility::handles (grasp at the resting pose and release at the shifted one, both
//     collision-free, approach included); it is "grasp-reachable" when its grasp transition alone
//     sampled collision-free at least once. The main figure is pick-reachable. Handles already
//     pick-reachable are dropped from the part's SRDF for later configurations of the same
//     (part, pose) job (they cannot become unreachable), which only saves time.
//   - matched: as tests/core/test_grasp_handles.cpp does: generate_handles(mesh, 0.001,
//     centre_of_mass, Panda gripper), a generated handle within 1 cm and 15 degrees (rotation angle
//     of g^-1 s) of the SRDF handle.
//   handle_reach [--samples N] [--placements P] [--yaws Y] [--threads T] [--on table|shelf]
//   (defaults 16, 3, 8, all cores, table; --placements 0: all of them; --placements upright: only
//   the mesh frame's z up, the lowest hull point on the table, as the benchmark stands its parts;
//   HANDLE_REACH_DEBUG=1 prints every configuration's failures and the resting poses skipped)
// Measured 2026-12-03 with the defaults: 44 of 76 SRDF handles reachable, 35 of them matched (11 s
// on 2 threads). The figure depends mostly on --placements: upright 31 (24 matched), 1: 18 (14),
// 2: 26 (22), 3: 44 (35), 4: 66 (50), 6: 75 (55), all: 76 (56) (samples 32, 8 yaws).
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <mutex>
#include <set>
#include <thread>
#include <string>
#include <vector>

#include "core/cell/cell_picks.h"
#include "core/demo/benchmark_scene.h"
#include "core/graph/constraint_graph.h"
#include "core/graph/pick_feasibility.h"
#include "core/model/mesh.h"
#include "core/model/srdf.h"
#include "core/parallel_for.h"
#include "core/part/grasp_handles.h"
#include "core/part/resting_placements.h"
#include "core/scene/collision_checker.h"
#include "core/scene/support.h"

using namespace demoplan;

namespace {

const std::string kData = DEMOPLAN_DATA_DIR;
const char* kParts[] = {"02", "03", "04", "05", "07", "08", "09", "12", "21"};

struct Part {
  std::string name;  // obj_0000XX
  SceneObject object;
  std::vector<RestingPlacement> placements;
  std::vector<bool> matched;  // per SRDF handle
  size_t generated = 0;
};

struct JobResult {
  std::set<std::string> pick_reachable, grasp_reachable;
  int configurations = 0, skipped = 0;
};

// The highest horizontal support polygon under (x, y) no higher than `below`: its z and furniture
// (-1 when there is none).
std::pair<double, int> support_under(const std::vector<SupportPolygon>& supports, const Eigen::Vector3d& at, double below) {
  double best = -1e9;
  int furniture = -1;
  for (const auto& s : supports) {
    if (s.furniture < 0 || s.vertices.size() < 3) continue;
    const PolygonPlane plane = polygon_plane(s.vertices);
    if (plane.normal.z() < 0.999) continue;
    const double z = plane.origin.z();
    if (z > below || z <= best) continue;
    if (projects_inside(plane, s.vertices, Eigen::Vector3d(at.x(), at.y(), z), 1e-9)) best = z, furniture = s.furniture;
  }
  return {best, furniture};
}

}  // namespace

int main(int argc, char** argv) {
  int samples = 16, n_placements = 3, yaws = 8;
  std::string where = "table";
  bool upright = false;  // --placements upright: the mesh frame's z up, as the benchmark stands them
  int threads = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string a = argv[i];
    const int v = std::atoi(argv[i + 1]);
    if (a == "--samples") samples = v;
    else if (a == "--placements" && std::string(argv[i + 1]) == "upright") upright = true, n_placements = 1;
    else if (a == "--placements") n_placements = v;
    else if (a == "--yaws") yaws = v;
    else if (a == "--threads") threads = v;
    else if (a == "--on") where = argv[i + 1];
    else {
      std::fprintf(stderr, "usage: handle_reach [--samples N] [--placements P] [--yaws Y] [--threads T] [--on table|shelf]\n");
      return 2;
    }
  }
  const auto t0 = std::chrono::steady_clock::now();
  const BenchmarkTask task = load_benchmark_task(kData, "shelf_1");
  const std::vector<int> poses = benchmark_pose_ids(task, "panda");
  std::vector<Scene> scenes;
  for (int p : poses) scenes.push_back(build_benchmark_scene(task, "panda", p));
  const ParallelGripper gripper = parallel_gripper(scenes.front().robot.model, scenes.front().robot.srdf);
  const double opening = scenes.front().robot.gripper().clearance;

  std::vector<Part> parts;
  for (const char* id : kParts) {
    Part part;
    part.name = std::string("obj_0000") + id;
    part.object.id = std::string("YCBV_") + id;
    part.object.model_name = part.name;
    part.object.model = load_urdf(kData + "/objects/ycbv/" + part.name + ".urdf");
    part.object.srdf = load_srdf(kData + "/objects/ycbv/srdf/" + part.name + ".srdf");
    const auto mesh = load_mesh(kData + "/objects/ycbv/meshes/" + part.name + ".obj");
    const Eigen::Vector3d com = centre_of_mass(*mesh, 0.001);
    std::vector<Eigen::Vector3d> points;
    for (const auto& v : mesh->vertices) points.push_back(v.cast<double>() * 0.001);
    part.placements = resting_placements(points, com);
    std::string faces;
    char buf[96];
    for (size_t i = 0; i < part.placements.size(); ++i) {
      const RestingPlacement& p = part.placements[i];
      std::snprintf(buf, sizeof buf, "%s%s(%.2f %.2f %.2f) %.0fdeg", i ? ", " : "",
                    !upright && static_cast<int>(i) == n_placements ? "| " : "", p.normal.x(), p.normal.y(), p.normal.z(),
                    p.tipping_angle * 180 / M_PI);
      faces += buf;
    }
    if (!upright) std::printf("%s: %zu resting placements (face normal in the part frame, tipping angle; '|' ends those used): %s\n",
                part.name.c_str(), part.placements.size(), faces.c_str());
    if (upright) {
      double low = 1e9;
      for (const auto& p : points) low = std::min(low, p.z());
      RestingPlacement r;
      r.part_on_plane = Pose(Eigen::Translation3d(0, 0, -low));
      part.placements = {r};
    } else if (n_placements > 0 && static_cast<int>(part.placements.size()) > n_placements) {
      part.placements.resize(n_placements);
    }
    const GraspReport r = generate_handles(*mesh, 0.001, com, gripper);
    part.generated = r.handles.size();
    for (const auto& s : part.object.srdf.handles) {
      bool found = false;
      for (const auto& g : r.handles) found |= handle_matches(g.frame.pose, s.pose);
      part.matched.push_back(found);
    }
    parts.push_back(std::move(part));
  }
  std::printf("shelf_1, panda poses %zu, parts on the %s, %d placements%s, %d yaws, %d samples per transition, "
              "gripper opening %.3f m\n", poses.size(), where.c_str(), n_placements,
              upright ? " (upright: the mesh frame's z up)" : n_placements <= 0 ? " (all)" : "", yaws, samples, opening);

  // Jobs: (part, robot pose).
  const size_t n_jobs = parts.size() * scenes.size();
  std::vector<JobResult> results(n_jobs);
  std::atomic<int> finished{0};
  parallel_for(n_jobs, threads, [&](size_t j) {
    const Part& part = parts[j / scenes.size()];
    const size_t pose_index = j % scenes.size();
    const Scene& base = scenes[pose_index];
    const SceneState base_start = benchmark_start_state(task, base);
    const std::vector<SupportPolygon> supports = support_polygons(base);
    JobResult& res = results[j];
    // Where shelf_1's parts rest on the table (YCBV_02 at its start, YCBV_05 at its goal: it
    // starts on the shelf's top), each in place of that part, the other at its start pose.
    struct Spot {
      size_t slot;
      Eigen::Vector3d at;
      double top;
    };
    std::vector<Spot> spots;
    for (size_t slot = 0; slot < base.objects.size(); ++slot)
      for (const Pose& p : task.subgoal_poses[slot]) {
        const Eigen::Vector3d at = p.translation();
        const auto [top, furniture] = support_under(supports, at, at.z());
        if (furniture < 0 || base.furniture[furniture].kind != where) continue;
        bool seen = false;
        for (const Spot& s : spots) seen |= s.slot == slot && (s.at - at).head<2>().norm() < 0.01;
        if (!seen) spots.push_back({slot, at, top});
      }
    for (const Spot& spot : spots) {
      const size_t slot = spot.slot;
      const Eigen::Vector3d at = spot.at;
      const double top = spot.top;
      for (size_t pl = 0; pl < part.placements.size(); ++pl)
        for (int k = 0; k < yaws; ++k) {
          // The part's SRDF, without the handles already found pick-reachable in this job.
          SceneObject object = part.object;
          object.srdf.handles.clear();
          for (const auto& h : part.object.srdf.handles)
            if (!res.pick_reachable.count(h.name)) object.srdf.handles.push_back(h);
          bool any_open = false;
          for (const auto& h : object.srdf.handles) any_open |= h.clearance <= opening;
          if (!any_open) continue;
          Scene scene = base;
          scene.objects[slot] = object;
          const Pose rest = Eigen::Translation3d(at.x(), at.y(), top + 0.001) *
                            Eigen::AngleAxisd(2 * M_PI * k / yaws, Eigen::Vector3d::UnitZ()) *
                            part.placements[pl].part_on_plane;
          SceneState start = base_start;
          start.objects[slot] = rest;
          const CollisionChecker checker(scene);
          CollisionData data = checker.make_data();
          bool touches = false;
          for (const auto& c : checker.collisions(start, data)) {
            const std::string me = "object/" + object.id;
            const bool mine = c.first == me || c.second == me;
            const bool robot = c.first.rfind("robot/", 0) == 0 || c.second.rfind("robot/", 0) == 0;
            touches |= mine && !robot;
            if (mine && !robot && std::getenv("HANDLE_REACH_DEBUG")) std::fprintf(stderr, "touch %s / %s\n", c.first.c_str(), c.second.c_str());
          }
          if (touches) {
            ++res.skipped;
            continue;
          }
          ++res.configurations;
          Pose to = rest;
          to.translation().y() += 0.02;
          const std::vector<ScriptedPick> one{{static_cast<int>(slot), to}};
          const Demonstration demo = demonstration_from_picks(scene, start, one, scene.name);
          const ConstraintGraph graph = build_constraint_graph(scene, demo);
          const std::uint64_t seed = 1000003ull * j + 1009ull * (slot * 64 + pl) + k + 1;
          const FeasibilityReport f = assess_picks(scene, graph, checker, samples, seed);
          if (std::getenv("HANDLE_REACH_DEBUG"))
            std::fprintf(stderr, "%s pose %d slot %zu placement %zu yaw %d top %.3f: %s\n", part.name.c_str(), poses[pose_index], slot, pl, k, top,
                         f.summary(scene).c_str());
          for (const auto& name : f.picks.front().handles) res.pick_reachable.insert(name);
          const GraphPick& gp = graph.picks.front();
          for (size_t w = 0; w < gp.grasp_states.size(); ++w)
            if (f.transitions[gp.grasp[w]].collision_free > 0)
              res.grasp_reachable.insert(object.srdf.handles[graph.states[gp.grasp_states[w]].handle].name);
        }
    }
  }, [&](size_t j) {
    std::fprintf(stderr, "[%3d/%zu] %s pose %d: %zu pick-reachable, %d configurations (%d skipped) %.0f s\n",
                 ++finished, n_jobs, parts[j / scenes.size()].name.c_str(), poses[j % scenes.size()],
                 results[j].pick_reachable.size(), results[j].configurations, results[j].skipped,
                 std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  });

  int t_handles = 0, t_reach = 0, t_grasp = 0, t_matched = 0, t_matched_reach = 0, t_matched_grasp = 0;
  std::printf("%-11s %5s %9s %9s %7s %14s %15s  %s\n", "part", "srdf", "pick-rch", "grasp-rch", "matched",
              "matched&pick", "matched&grasp", "pick-reachable but unmatched");
  for (size_t i = 0; i < parts.size(); ++i) {
    const Part& part = parts[i];
    std::set<std::string> pick, grasp;
    for (size_t p = 0; p < scenes.size(); ++p) {
      pick.insert(results[i * scenes.size() + p].pick_reachable.begin(), results[i * scenes.size() + p].pick_reachable.end());
      grasp.insert(results[i * scenes.size() + p].grasp_reachable.begin(), results[i * scenes.size() + p].grasp_reachable.end());
    }
    int n = 0, r = 0, g = 0, m = 0, mr = 0, mg = 0;
    std::string missing, unreachable;
    for (size_t h = 0; h < part.object.srdf.handles.size(); ++h) {
      const std::string& name = part.object.srdf.handles[h].name;
      const bool in_pick = pick.count(name) > 0, in_grasp = grasp.count(name) > 0 || in_pick;
      ++n, r += in_pick, g += in_grasp, m += part.matched[h];
      mr += in_pick && part.matched[h], mg += in_grasp && part.matched[h];
      if (in_pick && !part.matched[h]) missing += (missing.empty() ? "" : " ") + name;
      if (!in_pick) unreachable += (unreachable.empty() ? "" : " ") + name;
    }
    std::printf("%-11s %5d %9d %9d %7d %14d %15d  %s\n", part.name.c_str(), n, r, g, m, mr, mg,
                missing.empty() ? "-" : missing.c_str());
    std::printf("%-11s   not pick-reachable: %s\n", "", unreachable.empty() ? "-" : unreachable.c_str());
    t_handles += n, t_reach += r, t_grasp += g, t_matched += m, t_matched_reach += mr, t_matched_grasp += mg;
  }
  std::printf("%-11s %5d %9d %9d %7d %14d %15d\n", "total", t_handles, t_reach, t_grasp, t_matched, t_matched_reach,
              t_matched_grasp);
  std::printf("(%.0f s)\n", std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  return 0;
}
