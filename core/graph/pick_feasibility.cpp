#include "core/graph/pick_feasibility.h"

#include <chrono>
#include <random>

#include "core/graph/state_validity.h"

namespace demoplan {

std::string TransitionSampling::main_failure() const {
  // Once the handle was reached, what stopped it there says more than the misses of the others.
  std::string best;
  int most = 0;
  for (const auto& [why, n] : failures)
    if (n > most && (projected == 0 || why.rfind("in collision", 0) == 0)) best = why, most = n;
  return best + " (" + std::to_string(most) + " of " + std::to_string(samples) + ")";
}

bool FeasibilityReport::feasible() const {
  for (const auto& p : picks)
    if (!p.feasible()) return false;
  return true;
}

std::string FeasibilityReport::summary(const Scene& scene) const {
  std::string s;
  for (const auto& p : picks)
    if (!p.feasible())
      s += "pick " + std::to_string(p.pick + 1) + " (" + scene.objects[p.object].id + ") cannot be done: " + p.reason +
           "\n";
  return s;
}

FeasibilityReport assess_picks(const Scene& scene, const ConstraintGraph& graph, const CollisionChecker& checker,
                               int samples, std::uint64_t seed) {
  const ConstraintProjector projector(scene, graph);
  const StateValidity validity(scene, graph, checker);
  CollisionData data = checker.make_data();
  std::mt19937_64 rng(seed);

  FeasibilityReport r;
  r.transitions.resize(graph.transitions.size());
  for (size_t i = 0; i < graph.transitions.size(); ++i) {
    TransitionSampling& st = r.transitions[i];
    st.samples = samples;
    for (int k = 0; k < samples; ++k) {
      const auto t0 = std::chrono::steady_clock::now();
      const TransitionSample s = projector.sample_on_transition(static_cast<int>(i), rng);
      r.projection_seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      if (!s.ok) {
        ++st.failures[s.failure.substr(0, s.failure.find(" ("))];
        continue;
      }
      ++st.projected;
      CollisionPair hit;
      if (validity.transition_free(s, data, &hit)) ++st.collision_free;
      else ++st.failures["in collision: " + hit.first + " / " + hit.second];
    }
  }

  // Group by pick: the grasp states of pick k, each with its grasp and release transitions.
  for (size_t k = 0; k < graph.picks.size(); ++k) {
    const GraphPick& gp = graph.picks[k];
    PickFeasibility p;
    p.pick = static_cast<int>(k);
    p.object = gp.object;
    for (size_t w = 0; w < gp.grasp_states.size(); ++w) {
      const GraphState& state = graph.states[gp.grasp_states[w]];
      const TransitionSampling& grasp = r.transitions[gp.grasp[w]];
      const TransitionSampling& release = r.transitions[gp.release[w]];
      const std::string handle = scene.objects[state.object].srdf.handles[state.handle].name;
      if (grasp.collision_free > 0 && release.collision_free > 0) {
        p.handles.push_back(handle);
        continue;
      }
      std::string why;
      if (grasp.collision_free == 0) why += "grasp: " + grasp.main_failure();
      if (release.collision_free == 0)
        why += std::string(why.empty() ? "" : ", ") + "release: " + release.main_failure();
      p.reason += (p.reason.empty() ? "" : "; ") + handle + " (" + why + ")";
    }
    if (p.feasible()) p.reason.clear();
    else p.reason = "no handle grasps and releases collision-free in " + std::to_string(samples) + " samples each: " + p.reason;
    r.picks.push_back(std::move(p));
  }
  return r;
}

}  // namespace demoplan
