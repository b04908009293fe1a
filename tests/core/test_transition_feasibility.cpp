// Every pick of every benchmark demonstration can be done: for each (task, robot) some robot
// base pose has a handle of the moved object whose grasp and release transitions both sample
// collision-free. Individual transitions may never be collision-free: a handle whose gripper
// pose puts the hand inside the part (YCBV_05's handleZmy), or one that approaches through the
// table. Those are printed with their reason, not asserted.
//
// waiter_0 with the KMR is planned with the deck poses chosen by place_on_deck() (with the
// paper's handles of YCBV_05 it keeps the demonstrator's tray offsets; with the 2024 handles the
// last pick, YCBV_05 from the deck to the shelf, needs the bottle moved: test_deck_placement).
#include <gtest/gtest.h>

#include <map>
#include <set>

#include "core/demo/benchmark_demonstration.h"
#include "core/placement/deck_placement.h"
#include "core/demo/benchmark_scene.h"
#include "core/graph/projector.h"
#include "core/graph/state_validity.h"

using namespace demoplan;

static const std::string kData = DEMOPLAN_DATA_DIR;

namespace {

struct Case {
  std::string task, robot;
};

void PrintTo(const Case& c, std::ostream* os) { *os << c.task << "_" << c.robot; }

class PickFeasibility : public ::testing::TestWithParam<Case> {};

}  // namespace

TEST_P(PickFeasibility, EveryPickHasAHandleThatGraspsAndReleasesCollisionFree) {
  const Case c = GetParam();
  const BenchmarkTask task = load_benchmark_task(kData, c.task);
  static MeshCache meshes;
  std::map<int, std::set<std::string>> feasible_handles;  // pick -> handles with both ends free
  std::map<std::string, std::string> never;              // transition -> last failure
  std::set<std::string> ever_free;
  int picks = 0;
  for (int pose : benchmark_pose_ids(task, c.robot)) {
    const Scene scene = build_benchmark_scene(task, c.robot, pose, {false, &meshes});
    const ConstraintGraph graph = build_constraint_graph(
        scene, place_on_deck(scene, demonstration_from_benchmark(task, scene, PoseSource::Subgoals)).demonstration);
    const ConstraintProjector projector(scene, graph);
    const CollisionChecker checker(scene);
    const StateValidity validity(scene, graph, checker);
    CollisionData data = checker.make_data();
    std::mt19937_64 rng(1);
    picks = static_cast<int>(graph.placement_sequence.size()) - 1;
    std::map<std::pair<int, std::string>, int> ends_free;  // (pick, handle) -> grasp|release bits
    for (size_t t = 0; t < graph.transitions.size(); ++t) {
      const GraphTransition& tr = graph.transitions[t];
      const GraphState& g = graph.states[tr.kind == TransitionKind::Grasp ? tr.to : tr.from];
      const std::string handle = scene.objects[tr.object].srdf.handles[tr.handle].name;
      for (int k = 0; k < 150; ++k) {
        const TransitionSample s = projector.sample_on_transition(static_cast<int>(t), rng);
        CollisionPair hit;
        if (s.ok && validity.transition_free(s, data, &hit)) {
          ends_free[{g.step, handle}] |= tr.kind == TransitionKind::Grasp ? 1 : 2;
          ever_free.insert(tr.name);
          break;
        }
        never[tr.name] = s.ok ? "collision " + hit.first + " / " + hit.second : s.failure.substr(0, s.failure.find(" ("));
      }
    }
    for (const auto& [key, bits] : ends_free)
      if (bits == 3) feasible_handles[key.first].insert(key.second);
  }
  for (int p = 0; p < picks; ++p)
    EXPECT_FALSE(feasible_handles[p].empty()) << c.task << " " << c.robot << ": pick " << p << " has no feasible handle";
  for (const auto& [name, why] : never)
    if (!ever_free.count(name)) std::printf("  never collision-free on any pose: %s (%s)\n", name.c_str(), why.c_str());
}

INSTANTIATE_TEST_SUITE_P(Benchmark, PickFeasibility,
                         ::testing::Values(Case{"shelf_0", "panda"}, Case{"shelf_1", "panda"}, Case{"shelf_1", "ur5"},
                                           Case{"shelf_2", "ur5"}, Case{"tunnel_0", "panda"},
                                           Case{"waiter_0", "kmr_iiwa"}),
                         [](const auto& info) { return info.param.task + "_" + info.param.robot; });
