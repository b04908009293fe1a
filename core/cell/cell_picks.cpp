#include "core/cell/cell_picks.h"

#include <random>

#include "core/error.h"
#include "core/graph/constraint_graph.h"
#include "core/graph/pick_feasibility.h"
#include "core/io/json_file.h"
#include "core/scene/collision_checker.h"
#include "core/scene/resting_pose_sampler.h"

namespace demoplan {

std::vector<ScriptedPick> load_pick_script(const std::string& file, const Scene& scene) {
  const Json json = read_json_file(file);
  const JsonField root(json, file);
  check_format(root, "demoplan-pick-script", 1, "pick script");
  std::vector<ScriptedPick> out;
  const JsonField picks = root["picks"];
  for (size_t i = 0; i < picks.size(); ++i) {
    const JsonField p = picks[i];
    ScriptedPick pick;
    pick.part = scene.object_index(p["part"].string());
    if (pick.part < 0) p["part"].fail("no part '" + p["part"].string() + "' in " + scene.name);
    const JsonField to = p["to"];
    Eigen::Vector3d xyz = Eigen::Vector3d::Zero(), rpy = Eigen::Vector3d::Zero();
    for (const auto& [key, v] : {std::pair<const char*, Eigen::Vector3d*>{"xyz", &xyz}, {"rpy", &rpy}})
      if (to.has(key)) {
        const Eigen::VectorXd x = to[key].vector();
        if (x.size() != 3) to[key].fail("must have 3 numbers");
        *v = x;
      }
    pick.to = pose_from_xyz_rpy(xyz, rpy);
    out.push_back(pick);
  }
  if (out.empty()) picks.fail("lists no pick");
  return out;
}

Demonstration demonstration_from_picks(const Scene& scene, const SceneState& start, const std::vector<ScriptedPick>& picks,
                                       const std::string& name, const PickTiming& t) {
  Demonstration d;
  d.task = name;
  d.fps = t.fps;
  for (const auto& o : scene.objects) d.object_ids.push_back(o.id);
  PoseList poses = start.objects;
  int frame = t.lead_in;
  for (const ScriptedPick& p : picks) {
    d.events.push_back({frame, p.part, EventType::Grasp, 1.0, poses, {}});
    poses[p.part] = p.to;
    frame += t.carry;
    d.events.push_back({frame, p.part, EventType::Release, 1.0, poses, {}});
    frame += t.between;
  }
  return d;
}

RandomPickReport random_picks(const Scene& scene, const SceneState& start, int count, std::uint64_t seed) {
  RandomPickReport r;
  std::mt19937_64 rng(seed);
  const RestingPoseSampler sampler(scene);
  const CollisionChecker checker(scene);
  CollisionData data = checker.make_data();
  if (scene.objects.empty()) {
    r.failure = "the cell has no part to pick";
    return r;
  }
  if (sampler.empty()) {
    r.failure = "the cell has no support to put a part down on";
    return r;
  }
  SceneState now = start;
  int last = -1;
  while (static_cast<int>(r.picks.size()) < count) {
    bool found = false;
    for (int draw = 0; draw < 200 && !found; ++draw) {
      ++r.attempts;
      const int n = static_cast<int>(scene.objects.size());
      int part = static_cast<int>(rng() % n);
      if (n > 1 && part == last) part = (part + 1) % n;
      const std::optional<Pose> to = sampler.sample(part, rng);
      if (!to) continue;
      // Put down away from where it was (a pick that hardly moves it shows nothing).
      if ((to->translation() - now.objects[part].translation()).norm() < 0.1) continue;
      SceneState after = now;
      after.objects[part] = *to;
      if (checker.in_collision(after, data)) continue;
      // Doable: some handle grasps it here and releases it there.
      std::vector<ScriptedPick> one{{part, *to}};
      const Demonstration demo = demonstration_from_picks(scene, now, one, scene.name);
      const ConstraintGraph graph = build_constraint_graph(scene, demo);
      const FeasibilityReport feasibility = assess_picks(scene, graph, checker, 12, rng());
      if (!feasibility.feasible()) continue;
      r.picks.push_back(one.front());
      now = after;
      last = part;
      found = true;
    }
    if (!found) {
      r.failure = "no doable pick found in 200 draws after " + std::to_string(r.picks.size()) + " picks";
      break;
    }
  }
  return r;
}

}  // namespace demoplan
