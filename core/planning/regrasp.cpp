#include "core/planning/regrasp.h"

#include <cstdio>

#include "core/graph/projector.h"
#include "core/graph/state_validity.h"
#include "core/scene/resting_pose_sampler.h"
#include "core/error.h"

namespace demoplan {

namespace {

// Index of the k-th grasp event, or -1.
int grasp_event(const Demonstration& demo, int pick) {
  int k = 0;
  for (size_t i = 0; i < demo.events.size(); ++i)
    if (demo.events[i].type == EventType::Grasp && k++ == pick) return static_cast<int>(i);
  return -1;
}

// What the samplers below share: the checks, and what runs between samples.
struct Sampling {
  const ConstraintProjector& projector;
  const StateValidity& validity;
  CollisionData& data;
  std::mt19937_64& rng;
  const StopCondition& stop;
  const std::function<void()>& tick;
  int samples;
};

// Whether `transition` has a collision-free sample within `samples` draws.
bool sampled_free(Sampling& s, int transition) {
  for (int k = 0; k < s.samples && !s.stop.should_stop(); ++k) {
    const TransitionSample t = s.projector.sample_on_transition(transition, s.rng);
    const bool free = t.ok && s.validity.transition_free(t, s.data);
    if (s.tick) s.tick();
    if (free) return true;
  }
  return false;
}

// Whether some handle of graph pick k both grasps and releases collision-free.
bool pick_possible(Sampling& s, const ConstraintGraph& graph, int k) {
  const GraphPick& p = graph.picks[static_cast<size_t>(k)];
  for (size_t w = 0; w < p.grasp_states.size(); ++w)
    if (sampled_free(s, p.release[w]) && sampled_free(s, p.grasp[w])) return true;
  return false;
}

}  // namespace

Demonstration with_regrasp(const Demonstration& demo, const Regrasp& r) {
  const int g = grasp_event(demo, r.pick);
  if (g < 0 || g + 1 >= static_cast<int>(demo.events.size()))
    throw InputError("demonstration", "events", "pick " + std::to_string(r.pick + 1) + " does not exist");
  Demonstration out = demo;
  const ContactEvent& grasp = demo.events[static_cast<size_t>(g)];
  const ContactEvent& release = demo.events[static_cast<size_t>(g) + 1];
  ContactEvent put_down = grasp;  // the other parts stay where they are during the pick
  put_down.type = EventType::Release;
  put_down.frame = grasp.frame + (release.frame - grasp.frame) / 2;
  put_down.confidence = 1.0;
  put_down.poses[static_cast<size_t>(grasp.object)] = r.placement;
  if (!put_down.pose_frames.empty()) put_down.pose_frames[static_cast<size_t>(grasp.object)].clear();
  ContactEvent take_again = put_down;
  take_again.type = EventType::Grasp;
  out.events.insert(out.events.begin() + g + 1, {put_down, take_again});
  return out;
}

std::vector<Regrasp> find_regrasps(const Scene& scene, const Demonstration& demo, const CollisionChecker& checker,
                                   int pick, int count, std::mt19937_64& rng, const StopCondition& stop,
                                   int attempts, int samples, const std::function<void()>& tick) {
  std::vector<Regrasp> found;
  const int g = grasp_event(demo, pick);
  if (g < 0) return found;
  const RestingPoseSampler sampler(scene);
  CollisionData data = checker.make_data();
  for (int a = 0; a < attempts && static_cast<int>(found.size()) < count && !stop.should_stop(); ++a) {
    Regrasp r;
    r.pick = pick;
    r.object = demo.events[static_cast<size_t>(g)].object;
    const std::optional<Pose> pose = sampler.sample(r.object, rng);
    if (!pose) continue;
    r.placement = *pose;
    const ConstraintGraph graph = build_constraint_graph(scene, with_regrasp(demo, r));
    const ConstraintProjector projector(scene, graph);
    const StateValidity validity(scene, graph, checker);
    // The two halves: into the new placement (graph pick `pick`) and out of it (pick + 1).
    Sampling sampling{projector, validity, data, rng, stop, tick, samples};
    if (pick_possible(sampling, graph, pick) && pick_possible(sampling, graph, pick + 1) && !stop.should_stop())
      found.push_back(r);
  }
  return found;
}

std::string describe(const Scene& scene, const Regrasp& r) {
  const Eigen::Vector3d p = r.placement.translation();
  char where[96];
  std::snprintf(where, sizeof where, "(%.3f, %.3f, %.3f) m", p.x(), p.y(), p.z());
  return "pick " + std::to_string(r.pick + 1) + " (" + scene.objects[static_cast<size_t>(r.object)].id +
         "): put down at " + where + " and taken again";
}

}  // namespace demoplan
