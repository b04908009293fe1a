// The constraint graph built from the benchmark's demonstrations: its states against counts
// derived independently from the subgoal columns and the SRDF handles, the poses of the objects
// in every state, and the projector's samples against the constraints they must satisfy.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>
#include <map>
#include <memory>
#include <random>
#include <set>
#include <string>
#include <vector>

#include "core/demo/benchmark_demonstration.h"
#include "core/demo/benchmark_scene.h"
#include "core/error.h"
#include "core/graph/constraint_graph.h"
#include "core/graph/projector.h"
#include "core/graph/state_validity.h"
#include "core/model/kinematics.h"
#include "core/scene/collision_checker.h"

using namespace demoplan;

static const std::string kData = DEMOPLAN_DATA_DIR;

namespace {

const std::vector<std::string> kTasksWithSubgoals{"shelf_0", "shelf_1", "shelf_2", "tunnel_0", "waiter_0"};
constexpr double kGripperOpening = 0.08;  // clearance of every benchmark gripper (SRDF)

MeshCache& meshes() {
  static MeshCache cache;
  return cache;
}

const BenchmarkTask& task(const std::string& name) {
  static std::map<std::string, std::unique_ptr<BenchmarkTask>> cache;
  auto& t = cache[name];
  if (!t) t = std::make_unique<BenchmarkTask>(load_benchmark_task(kData, name));
  return *t;
}

const Scene& scene(const std::string& task_name, const std::string& robot, int pose) {
  static std::map<std::string, std::unique_ptr<Scene>> cache;
  auto& s = cache[task_name + " " + robot + " " + std::to_string(pose)];
  if (!s) s = std::make_unique<Scene>(build_benchmark_scene(task(task_name), robot, pose, {false, &meshes()}));
  return *s;
}

// The stated rule for "the same placement": every object within 1 mm and 1e-3 rad.
bool same_pose(const Pose& a, const Pose& b, double position = 1e-3, double rotation = 1e-3) {
  const Pose d = a.inverse() * b;
  return d.translation().norm() <= position && log3(d.linear()).norm() <= rotation;
}

double rotation_between(const Pose& a, const Pose& b) { return log3(a.linear().transpose() * b.linear()).norm(); }

// The placement sets the subgoal columns show: column 0 (start), then column 2k+1 after the
// k-th release.
std::vector<PoseList> column_placements(const BenchmarkTask& t) {
  std::vector<PoseList> sets;
  const size_t columns = t.subgoal_poses.front().size();
  for (size_t c = 0; c < columns; c += (c == 0 ? 1 : 2)) {
    PoseList set;
    for (const auto& row : t.subgoal_poses) set.push_back(row[c]);
    sets.push_back(set);
  }
  return sets;
}

size_t distinct_sets(const std::vector<PoseList>& sets) {
  size_t distinct = 0;
  for (size_t i = 0; i < sets.size(); ++i) {
    bool seen = false;
    for (size_t j = 0; j < i && !seen; ++j) {
      bool same = true;
      for (size_t o = 0; o < sets[i].size(); ++o) same = same && same_pose(sets[i][o], sets[j][o]);
      seen = same;
    }
    distinct += !seen;
  }
  return distinct;
}

// Runs f, which must throw InputError; returns what().
std::string input_error(const std::function<void()>& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  } catch (const std::exception& e) {
    ADD_FAILURE() << "threw a non-InputError exception: " << e.what();
    return "";
  }
  ADD_FAILURE() << "no exception thrown";
  return "";
}

void expect_mentions(const std::string& what, const std::vector<std::string>& parts) {
  for (const auto& p : parts) EXPECT_NE(what.find(p), std::string::npos) << "'" << p << "' not in: " << what;
}

struct Instance {
  std::string task, robot;
  int pose;
  std::string label() const { return task + " " + robot + " pose " + std::to_string(pose); }
};

// Every task with subgoals with every robot that has poses for it, at pose 0.
std::vector<Instance> instances() {
  std::vector<Instance> out;
  for (const auto& name : kTasksWithSubgoals)
    for (const auto& [robot, file] : task(name).robot_pose_files) {
      const auto ids = benchmark_pose_ids(task(name), robot);
      if (std::find(ids.begin(), ids.end(), 0) != ids.end()) out.push_back({name, robot, 0});
    }
  return out;
}

}  // namespace

// ---------------------------------------------------------------------------------------------
// Structure.

// The rules the counts follow:
//  * placement states: one per distinct placement set of the demonstration, that is the start
//    (subgoal column 0) and the set after each release (column 2k+1), so (number of contact
//    segments + 1) unless two of these sets coincide (every object within 1 mm and 1e-3 rad);
//  * grasp states: for each contact segment, one per SRDF handle of the moved object whose
//    clearance is at most the gripper's opening (0.08 m);
//  * transitions: a grasp and a release per grasp state.
TEST(ConstraintGraph, StateCountsFollowTheDemonstrationAndTheHandles) {
  const auto all = instances();
  EXPECT_EQ(all.size(), 4u * 3 + 1);  // shelf_0..2, tunnel_0 x (panda, ur5, kmr_iiwa); waiter_0 x kmr_iiwa
  for (const auto& in : all) {
    SCOPED_TRACE(in.label());
    const BenchmarkTask& t = task(in.task);
    const Scene& s = scene(in.task, in.robot, in.pose);
    const Demonstration demo = demonstration_from_subgoals(t);
    const ConstraintGraph g = build_constraint_graph(s, demo);
    const auto segments = contact_segments(t);

    // For these tasks no two placement sets coincide: counted from the columns themselves.
    const auto sets = column_placements(t);
    ASSERT_EQ(sets.size(), segments.size() + 1);
    const size_t placements = distinct_sets(sets);
    EXPECT_EQ(placements, segments.size() + 1);

    EXPECT_EQ(s.robot.gripper().clearance, kGripperOpening);
    size_t grasps = 0;
    for (const auto& seg : segments)
      for (const auto& h : s.objects[seg.object].srdf.handles) grasps += h.clearance <= kGripperOpening;

    EXPECT_EQ(g.states_of_kind(StateKind::Placement).size(), placements);
    EXPECT_EQ(g.placement_sequence.size(), placements);
    EXPECT_EQ(g.states_of_kind(StateKind::Grasp).size(), grasps);
    EXPECT_EQ(g.states.size(), placements + grasps);
    EXPECT_EQ(g.transitions.size(), 2 * grasps);
    ASSERT_FALSE(g.placement_sequence.empty());
    EXPECT_EQ(g.start_state, g.placement_sequence.front());
    EXPECT_EQ(g.goal_state, g.placement_sequence.back());
    EXPECT_EQ(g.states[g.start_state].name, "P0");
    EXPECT_EQ(g.states[g.goal_state].name, "P" + std::to_string(segments.size()));
    EXPECT_EQ(g.q_start, s.robot.initial_configuration);
    EXPECT_EQ(g.q_goal, s.robot.initial_configuration);

    // Gripper joints: the fingers, open at their upper limit; the rest reaches.
    EXPECT_FALSE(g.gripper_joints.empty());
    EXPECT_EQ(g.reach_joints.size() + g.gripper_joints.size(), static_cast<size_t>(s.robot.model.nq));
    ASSERT_EQ(g.gripper_open.size(), static_cast<long>(g.gripper_joints.size()));
    for (size_t k = 0; k < g.gripper_joints.size(); ++k)
      EXPECT_EQ(g.gripper_open[static_cast<long>(k)], s.robot.model.upper_limits()[g.gripper_joints[k]]);

    // Grasp states of segment k: the moved object, every usable handle once, between the
    // placements k and k+1, with a grasp and a release transition each.
    for (const auto& st : g.states) {
      if (st.kind != StateKind::Grasp) continue;
      SCOPED_TRACE(st.name);
      ASSERT_GE(st.step, 0);
      ASSERT_LT(st.step, static_cast<int>(segments.size()));
      EXPECT_EQ(st.object, segments[st.step].object);
      ASSERT_GE(st.handle, 0);
      ASSERT_LT(st.handle, static_cast<int>(s.objects[st.object].srdf.handles.size()));
      EXPECT_LE(s.objects[st.object].srdf.handles[st.handle].clearance, kGripperOpening);
    }
    for (size_t k = 0; k < segments.size(); ++k) {
      std::vector<int> handles;
      for (const auto& st : g.states)
        if (st.kind == StateKind::Grasp && st.step == static_cast<int>(k)) handles.push_back(st.handle);
      std::sort(handles.begin(), handles.end());
      EXPECT_TRUE(std::adjacent_find(handles.begin(), handles.end()) == handles.end()) << "segment " << k;
    }
    for (size_t i = 0; i < g.transitions.size(); ++i) {
      const GraphTransition& tr = g.transitions[i];
      SCOPED_TRACE(tr.name);
      const bool grasp = tr.kind == TransitionKind::Grasp;
      const GraphState& placement = g.states[grasp ? tr.from : tr.to];
      const GraphState& held = g.states[grasp ? tr.to : tr.from];
      ASSERT_EQ(placement.kind, StateKind::Placement);
      ASSERT_EQ(held.kind, StateKind::Grasp);
      EXPECT_EQ(tr.object, held.object);
      EXPECT_EQ(tr.handle, held.handle);
      EXPECT_EQ(tr.edge_state(), grasp ? tr.from : tr.to);
      // Placement k before grasp k, placement k+1 after it.
      EXPECT_EQ(placement.name, "P" + std::to_string(held.step + (grasp ? 0 : 1)));
      // The grasp state's other objects rest where they rest before the pick.
      const GraphState& before = g.states[g.placement_sequence[held.step]];
      for (size_t o = 0; o < s.objects.size(); ++o)
        if (static_cast<int>(o) != held.object) {
          EXPECT_EQ(held.objects[o].pose.matrix(), before.objects[o].pose.matrix());
        }
    }
    // Each grasp state has exactly one way in and one way out.
    for (int gs : g.states_of_kind(StateKind::Grasp)) {
      int in_count = 0, out_count = 0;
      for (const auto& tr : g.transitions) {
        in_count += tr.to == gs && tr.kind == TransitionKind::Grasp;
        out_count += tr.from == gs && tr.kind == TransitionKind::Release;
      }
      EXPECT_EQ(in_count, 1) << g.states[gs].name;
      EXPECT_EQ(out_count, 1) << g.states[gs].name;
    }
  }
}

// In every placement state the objects are where the subgoal columns put them: column 0 in P0,
// column 2k+1 after the k-th release. The objects rest in the world.
void expect_placements_are_the_columns(const Instance& in) {
  SCOPED_TRACE(in.label());
  const BenchmarkTask& t = task(in.task);
  const Scene& s = scene(in.task, in.robot, in.pose);
  const ConstraintGraph g = build_constraint_graph(s, demonstration_from_subgoals(t));
  const auto sets = column_placements(t);
  ASSERT_EQ(g.placement_sequence.size(), sets.size());
  for (size_t k = 0; k < sets.size(); ++k) {
    const GraphState& p = g.states[g.placement_sequence[k]];
    SCOPED_TRACE(p.name);
    EXPECT_EQ(p.kind, StateKind::Placement);
    EXPECT_EQ(p.name, "P" + std::to_string(k));
    ASSERT_EQ(p.objects.size(), sets[k].size());
    for (size_t o = 0; o < sets[k].size(); ++o) {
      EXPECT_EQ(p.objects[o].link, -1) << "object " << o;
      EXPECT_TRUE(same_pose(p.objects[o].pose, sets[k][o]))
          << "object " << s.objects[o].id << " is " << (p.objects[o].pose.translation() - sets[k][o].translation()).norm()
          << " m and " << rotation_between(p.objects[o].pose, sets[k][o]) << " rad from column "
          << (k == 0 ? 0 : 2 * k - 1);
    }
    // The object moved in segment k-1 is exactly at its release pose.
    if (k > 0) {
      const int moved = contact_segments(t)[k - 1].object;
      EXPECT_EQ(p.objects[moved].pose.matrix(), t.subgoal_poses[moved][2 * k - 1].matrix());
    }
  }
}

TEST(ConstraintGraph, PlacementStatesAreTheSubgoalColumns) {
  for (const auto& in : instances())
    if (in.task != "waiter_0") expect_placements_are_the_columns(in);
}

// waiter_0: the demonstrator loads three objects on a tray, carries it, and unloads them on the
// shelf; the KMR's deck plays the tray. demonstration_from_subgoals() keeps every pose in the
// world, where the carried objects' columns cannot form placements (they move without a grasp
// between columns 5 and 6); demonstration_from_benchmark() puts them on the deck instead.
TEST(ConstraintGraph, WaiterObjectsOnTheDeckTravelWithTheRobot) {
  const Scene& s = scene("waiter_0", "kmr_iiwa", 0);
  const Demonstration demo = demonstration_from_benchmark(task("waiter_0"), s, PoseSource::Subgoals);
  ASSERT_TRUE(validate(demo).empty());
  const ConstraintGraph g = build_constraint_graph(s, demo);
  // Six picks (three onto the deck, three onto the shelf), no two placement sets alike.
  ASSERT_EQ(g.placement_sequence.size(), 7u);
  const int deck = s.robot.model.link_index("kmr_link");
  const auto& columns = task("waiter_0").subgoal_poses;
  // Start and goal: every object in the world at the first and last subgoal column.
  for (size_t o = 0; o < s.objects.size(); ++o) {
    const auto& start = g.states[g.start_state].objects[o];
    const auto& goal = g.states[g.goal_state].objects[o];
    EXPECT_EQ(start.link, -1);
    EXPECT_EQ(goal.link, -1);
    EXPECT_TRUE(start.pose.isApprox(columns[o].front(), 1e-12));
    EXPECT_TRUE(goal.pose.isApprox(columns[o].back(), 1e-12));
  }
  // After the three loading picks, all three ride on the deck; an object on the deck keeps one
  // pose relative to it from its release until its pick.
  const GraphState& loaded = g.states[g.placement_sequence[3]];
  for (size_t o = 0; o < s.objects.size(); ++o) EXPECT_EQ(loaded.objects[o].link, deck) << s.objects[o].id;
  for (int p : g.placement_sequence)
    for (size_t o = 0; o < s.objects.size(); ++o)
      if (g.states[p].objects[o].link == deck) {
        EXPECT_TRUE(g.states[p].objects[o].pose.isApprox(loaded.objects[o].pose, 1e-12));
      }
  // Riding objects follow the base: move it 1 m and they move 1 m.
  Eigen::VectorXd q = g.q_start;
  const SceneState here = scene_state(s, g, g.placement_sequence[3], q);
  q[0] += 1.0;
  const SceneState there = scene_state(s, g, g.placement_sequence[3], q);
  for (size_t o = 0; o < s.objects.size(); ++o)
    EXPECT_NEAR((there.objects[o].translation() - here.objects[o].translation()).norm(), 1.0, 1e-9);
}

TEST(ConstraintGraph, HandlesWiderThanTheGripperGiveNoGraspState) {
  Scene s = scene("shelf_1", "panda", 0);  // a copy to edit
  const Demonstration demo = demonstration_from_subgoals(task("shelf_1"));
  const ConstraintGraph full = build_constraint_graph(s, demo);
  // YCBV_02 (moved in the second segment): two of its handles now need 9 cm.
  const int o = s.object_index("YCBV_02");
  ASSERT_GE(o, 0);
  auto& handles = s.objects[o].srdf.handles;
  ASSERT_GE(handles.size(), 3u);
  handles[0].clearance = 0.09;
  handles[2].clearance = 0.0800001;
  const ConstraintGraph g = build_constraint_graph(s, demo);
  EXPECT_EQ(g.states_of_kind(StateKind::Grasp).size(), full.states_of_kind(StateKind::Grasp).size() - 2);
  EXPECT_EQ(g.transitions.size(), full.transitions.size() - 4);
  for (const auto& st : g.states)
    if (st.kind == StateKind::Grasp && st.object == o) {
      EXPECT_TRUE(st.handle != 0 && st.handle != 2) << st.name;
    }
  // None left: the demonstration cannot be planned, and the error says which event and object.
  for (auto& h : handles) h.clearance = 0.1;
  expect_mentions(input_error([&] { build_constraint_graph(s, demo); }),
                  {"events[2]", "YCBV_02", "no handle the gripper can open around"});
}

TEST(ConstraintGraph, CoincidingPlacementsAreOneState) {
  // shelf_1 with YCBV_02 put back within 0.5 mm and 0.5 mrad of where it was picked: the set
  // after the second release is the set after the first one.
  const Scene& s = scene("shelf_1", "panda", 0);
  Demonstration demo = demonstration_from_subgoals(task("shelf_1"));
  const int o = demo.events[2].object;
  Pose back = demo.events[2].poses[o];
  back.translation().z() += 0.0005;
  back.linear() = back.linear() * Eigen::AngleAxisd(0.0005, Eigen::Vector3d::UnitX()).toRotationMatrix();
  set_object_pose(demo, 3, o, back);
  ASSERT_TRUE(validate(demo).empty());
  const ConstraintGraph g = build_constraint_graph(s, demo);
  EXPECT_EQ(g.states_of_kind(StateKind::Placement).size(), 2u);
  ASSERT_EQ(g.placement_sequence.size(), 2u);
  EXPECT_EQ(g.goal_state, g.placement_sequence[1]);
  for (const auto& tr : g.transitions)
    if (tr.kind == TransitionKind::Release && g.states[tr.from].step == 1) {
      EXPECT_EQ(tr.to, g.placement_sequence[1]);
    }
  // 2 mm away: a third placement.
  back.translation().z() += 0.002;
  set_object_pose(demo, 3, o, back);
  EXPECT_EQ(build_constraint_graph(s, demo).states_of_kind(StateKind::Placement).size(), 3u);
}

TEST(ConstraintGraph, RejectsInvalidDemonstrationsAndOtherObjects) {
  const Scene& s = scene("shelf_1", "panda", 0);
  const Demonstration good = demonstration_from_subgoals(task("shelf_1"));

  Demonstration d = good;
  d.events.pop_back();
  expect_mentions(input_error([&] { build_constraint_graph(s, d); }),
                  {"demonstration of shelf_1", "YCBV_02 is grasped but never released"});
  d = good;
  d.events[2].frame = 3;  // out of order
  expect_mentions(input_error([&] { build_constraint_graph(s, d); }), {"shelf_1", "events[2]", "comes before"});
  d = good;
  d.events[1].poses[0].translation().x() = std::nan("");
  expect_mentions(input_error([&] { build_constraint_graph(s, d); }), {"events[1]", "YCBV_02", "not finite"});
  d = good;
  d.events.clear();
  expect_mentions(input_error([&] { build_constraint_graph(s, d); }), {"shelf_1", "no grasp or release event"});

  // Objects that are not the scene's.
  d = good;
  d.object_ids[1] = "YCBV_12";
  expect_mentions(input_error([&] { build_constraint_graph(s, d); }), {"objects[1]", "YCBV_12", "YCBV_05"});
  d = good;
  std::swap(d.object_ids[0], d.object_ids[1]);  // same objects, other order
  expect_mentions(input_error([&] { build_constraint_graph(s, d); }), {"objects[0]", "YCBV_05", "YCBV_02"});
  expect_mentions(input_error([&] { build_constraint_graph(s, demonstration_from_subgoals(task("shelf_0"))); }),
                  {"demonstration of shelf_0", "objects", "must list the scene's objects"});
}

TEST(ConstraintGraph, PoseFramesGivePlacementsOnARobotLink) {
  // shelf_1 with the KMR: YCBV_05 put down on the deck (kmr_link) instead of the shelf.
  const Scene& s = scene("shelf_1", "kmr_iiwa", 0);
  Demonstration demo = demonstration_from_subgoals(task("shelf_1"));
  const int o = demo.events[1].object;
  const int deck = s.robot.model.link_index("kmr_link");
  ASSERT_GE(deck, 0);
  Pose on_deck = Pose::Identity();
  on_deck.translation() << 0.1, -0.05, 0.75;
  for (size_t e = 1; e < demo.events.size(); ++e) {
    demo.events[e].pose_frames.assign(demo.object_ids.size(), "");
    demo.events[e].pose_frames[o] = "kmr_link";
    demo.events[e].poses[o] = on_deck;
  }
  ASSERT_TRUE(validate(demo).empty());
  const ConstraintGraph g = build_constraint_graph(s, demo);
  const GraphState& p1 = g.states[g.placement_sequence[1]];
  EXPECT_EQ(p1.objects[o].link, deck);
  EXPECT_EQ(p1.objects[o].pose.matrix(), on_deck.matrix());
  EXPECT_EQ(g.states[g.start_state].objects[o].link, -1);
  // Wherever the robot drives, the object rides on the deck; the others stay.
  const ConstraintProjector projector(s, g);
  std::mt19937_64 rng(5);
  for (int r = 0; r < 20; ++r) {
    const Eigen::VectorXd q = projector.sample_configuration(g.placement_sequence[1], rng);
    const SceneState ss = scene_state(s, g, g.placement_sequence[1], q);
    const Pose expected = link_pose(s.robot.model, q, s.robot.base, deck) * on_deck;
    EXPECT_TRUE(same_pose(ss.objects[o], expected, 1e-9, 1e-9));
    EXPECT_EQ(ss.objects[1 - o].matrix(), p1.objects[1 - o].pose.matrix());
  }
  // A frame that is no link of the robot.
  demo.events[1].pose_frames[o] = "kmr_deck";
  expect_mentions(input_error([&] { build_constraint_graph(s, demo); }), {"pose_frames", "kmr_deck", "kmr_iiwa"});
}

// ---------------------------------------------------------------------------------------------
// scene_state.

TEST(ConstraintGraph, SceneStateOfPlacementAndGraspStates) {
  for (const Instance& in : {Instance{"shelf_1", "panda", 0}, Instance{"tunnel_0", "ur5", 1}}) {
    SCOPED_TRACE(in.label());
    const Scene& s = scene(in.task, in.robot, in.pose);
    const ConstraintGraph g = build_constraint_graph(s, demonstration_from_subgoals(task(in.task)));
    const ConstraintProjector projector(s, g);
    std::mt19937_64 rng(3);
    for (size_t i = 0; i < g.states.size(); ++i) {
      const GraphState& st = g.states[i];
      SCOPED_TRACE(st.name);
      for (int r = 0; r < 10; ++r) {
        // Placement states leave the robot free: any q within the limits, fingers included.
        const Eigen::VectorXd q = projector.sample_configuration(static_cast<int>(i), rng);
        const SceneState ss = scene_state(s, g, static_cast<int>(i), q);
        EXPECT_EQ(ss.q, q);
        ASSERT_EQ(ss.objects.size(), s.objects.size());
        if (st.kind == StateKind::Placement) {
          EXPECT_TRUE(ss.attachments.empty());
          for (size_t o = 0; o < s.objects.size(); ++o) EXPECT_EQ(ss.objects[o].matrix(), st.objects[o].pose.matrix());
          continue;
        }
        for (size_t k = 0; k < g.gripper_joints.size(); ++k)
          EXPECT_EQ(q[g.gripper_joints[k]], g.gripper_open[static_cast<long>(k)]);
        ASSERT_EQ(ss.attachments.size(), 1u);
        EXPECT_EQ(ss.attachments[0].object, st.object);
        EXPECT_EQ(ss.attachments[0].link, s.robot.gripper_link);
        const Pose expected = gripper_pose(s, q) * s.objects[st.object].srdf.handles[st.handle].pose.inverse();
        EXPECT_LT((ss.objects[st.object].translation() - expected.translation()).norm(), 1e-9);
        EXPECT_LT(rotation_between(ss.objects[st.object], expected), 1e-9);
        // Held: the handle of the object is the gripper frame.
        const Pose handle = ss.objects[st.object] * s.objects[st.object].srdf.handles[st.handle].pose;
        EXPECT_TRUE(same_pose(handle, gripper_pose(s, q), 1e-9, 1e-9));
        EXPECT_TRUE(same_pose(s.robot.gripper().pose.inverse() * gripper_link_T_object(s, st.object, st.handle) *
                                  s.objects[st.object].srdf.handles[st.handle].pose,
                              Pose::Identity(), 1e-12, 1e-12));
        for (size_t o = 0; o < s.objects.size(); ++o)
          if (static_cast<int>(o) != st.object) {
            EXPECT_EQ(ss.objects[o].matrix(), st.objects[o].pose.matrix());
          }
      }
    }
  }
}

// ---------------------------------------------------------------------------------------------
// Projection: every sample satisfies its transition's constraints.

namespace {

struct ProjectionStats {
  int samples = 0, ok = 0, transitions_with_ok = 0;
};

ProjectionStats check_projections(const Instance& in, int samples_per_transition) {
  ProjectionStats stats;
  const Scene& s = scene(in.task, in.robot, in.pose);
  const ConstraintGraph g = build_constraint_graph(s, demonstration_from_subgoals(task(in.task)));
  const ConstraintProjector projector(s, g);
  const ProjectorOptions defaults;
  const Eigen::VectorXd lower = s.robot.model.lower_limits(), upper = s.robot.model.upper_limits();
  auto within_limits_and_open = [&](const Eigen::VectorXd& q) {
    for (long i = 0; i < q.size(); ++i)
      if (!(q[i] >= lower[i] && q[i] <= upper[i])) return ::testing::AssertionFailure() << "joint " << i << " = " << q[i];
    for (size_t k = 0; k < g.gripper_joints.size(); ++k)
      if (q[g.gripper_joints[k]] != g.gripper_open[static_cast<long>(k)])
        return ::testing::AssertionFailure() << "gripper joint " << g.gripper_joints[k] << " is not open";
    return ::testing::AssertionSuccess();
  };

  for (size_t i = 0; i < g.transitions.size(); ++i) {
    const GraphTransition& tr = g.transitions[i];
    const int ti = static_cast<int>(i);
    SCOPED_TRACE(in.label() + ": " + tr.name);
    const bool grasp = tr.kind == TransitionKind::Grasp;
    const GraspFrame& handle = s.objects[tr.object].srdf.handles[tr.handle];
    // The target, independently: the handle of the object where it rests in the placement state.
    int link = 0;
    const Pose target = projector.handle_target(ti, &link);
    EXPECT_EQ(link, -1);
    const Pose expected_target = g.states[grasp ? tr.from : tr.to].objects[tr.object].pose * handle.pose;
    EXPECT_TRUE(same_pose(target, expected_target, 1e-12, 1e-12));
    const Eigen::Vector3d axis = target.linear().col(0);
    const int steps = std::max(1, static_cast<int>(std::ceil(handle.clearance / defaults.approach_step)));

    std::mt19937_64 rng(1000 + i);
    int ok = 0;
    for (int n = 0; n < samples_per_transition; ++n) {
      const TransitionSample sample = projector.sample_on_transition(ti, rng);
      ++stats.samples;
      EXPECT_EQ(sample.transition, ti);
      EXPECT_EQ(sample.state_from, tr.from);
      EXPECT_EQ(sample.state_to, tr.to);
      if (!sample.ok) {
        EXPECT_FALSE(sample.failure.empty());
        continue;
      }
      ++ok;
      EXPECT_EQ(sample.path.size(), static_cast<size_t>(steps + 1));
      if (sample.path.size() < 2) continue;
      const Eigen::VectorXd& contact = grasp ? sample.q_to() : sample.q_from();
      const Eigen::VectorXd& away = grasp ? sample.q_from() : sample.q_to();
      const auto [position, rotation] = projector.handle_residual(ti, contact);
      EXPECT_LT(position, 1e-6);
      EXPECT_LT(rotation, 1e-6);
      // The pre-grasp / retreat end: the handle frame backed off by the clearance along x.
      Pose backed = target;
      backed.translation() -= handle.clearance * axis;
      const Pose at = gripper_pose(s, away);
      EXPECT_LT((at.translation() - backed.translation()).norm(), 1e-6);
      EXPECT_LT(rotation_between(at, backed), 1e-6);
      // Every configuration within the limits, fingers open; every waypoint on the axis,
      // oriented as the handle, between the contact and the backed-off end.
      double previous_depth = grasp ? -handle.clearance : 0.0;
      for (size_t k = 0; k < sample.path.size(); ++k) {
        const Eigen::VectorXd& q = sample.path[k];
        EXPECT_TRUE(within_limits_and_open(q)) << "waypoint " << k;
        const Pose w = gripper_pose(s, q);
        const Eigen::Vector3d offset = w.translation() - target.translation();
        const double depth = offset.dot(axis);
        EXPECT_LT((offset - depth * axis).norm(), 1e-6) << "waypoint " << k;
        EXPECT_LT(rotation_between(w, target), 1e-6) << "waypoint " << k;
        EXPECT_GE(depth, -handle.clearance - 1e-6);
        EXPECT_LE(depth, 1e-6);
        // Monotone along the axis: in towards the handle (grasp) or out (release).
        if (k > 0) {
          if (grasp) EXPECT_GT(depth, previous_depth);
          else EXPECT_LT(depth, previous_depth);
        }
        previous_depth = depth;
      }
      // The projection alone.
      const IkResult r = projector.project(ti, projector.sample_configuration(tr.from, rng), rng);
      if (r.success) {
        const auto [p2, r2] = projector.handle_residual(ti, r.q);
        EXPECT_LT(p2, 1e-6);
        EXPECT_LT(r2, 1e-6);
        EXPECT_TRUE(within_limits_and_open(r.q));
      }
    }
    stats.ok += ok;
    stats.transitions_with_ok += ok > 0;
  }
  std::printf("[ info ] %s: %d of %d transition samples satisfy their constraints; %d of %zu transitions sampled\n",
              in.label().c_str(), stats.ok, stats.samples, stats.transitions_with_ok, g.transitions.size());
  return stats;
}

}  // namespace

TEST(ConstraintProjector, EverySampleSatisfiesItsTransition) {
  constexpr int kSamplesPerTransition = 200;
  for (const Instance& in : {Instance{"shelf_1", "panda", 0}, Instance{"tunnel_0", "ur5", 1}}) {
    const ProjectionStats st = check_projections(in, kSamplesPerTransition);
    // The samples are checked above; enough of them must exist for that to mean something.
    EXPECT_GT(st.ok, st.samples / 20) << in.label();
    EXPECT_GE(st.transitions_with_ok * 2, st.samples / kSamplesPerTransition) << in.label();
  }
}

// How many transitions of shelf_1 (panda, pose 0) have a collision-free sample (both ends and
// the straight move, no allowed contacts) among the first seeded tries; with the paper's handles
// of YCBV_05 every pick has a handle whose grasp and release both do (with the 2024 handles the
// bottle's pick has none).
TEST(ConstraintProjector, EveryPickOfShelf1FromPandaPose0HasAFreeHandle) {
  const auto t0 = std::chrono::steady_clock::now();
  const Scene& s = scene("shelf_1", "panda", 0);
  const ConstraintGraph g = build_constraint_graph(s, demonstration_from_subgoals(task("shelf_1")));
  const ConstraintProjector projector(s, g);
  const CollisionChecker checker(s);
  const StateValidity validity(s, g, checker);
  auto data = checker.make_data();
  constexpr int kTries = 300;
  int sampleable = 0, ok_samples = 0, free_samples = 0, tries = 0;
  std::map<std::pair<int, int>, int> ends_free;  // (pick, handle) -> grasp (1) | release (2)
  for (size_t i = 0; i < g.transitions.size(); ++i) {
    std::mt19937_64 rng(77 + i);
    bool found = false;
    int ok = 0, free = 0;
    CollisionPair hit;
    std::string last_hit;
    for (int n = 0; n < kTries && !found; ++n) {
      ++tries;
      const TransitionSample sample = projector.sample_on_transition(static_cast<int>(i), rng);
      if (!sample.ok) continue;
      ++ok;
      if (validity.transition_free(sample, data, &hit)) {
        ++free;
        found = true;
      } else {
        last_hit = hit.first + " - " + hit.second;
      }
    }
    ok_samples += ok;
    free_samples += free;
    sampleable += found;
    const GraphTransition& tr = g.transitions[i];
    const bool grasp = tr.kind == TransitionKind::Grasp;
    if (found) ends_free[{g.states[grasp ? tr.to : tr.from].step, tr.handle}] |= grasp ? 1 : 2;
    std::printf("[ info ]   %-40s %s (%d constraint-satisfying samples%s%s)\n", g.transitions[i].name.c_str(),
                found ? "collision-free" : "no free sample", ok, last_hit.empty() ? "" : ", last hit ",
                last_hit.c_str());
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::printf("[ info ] shelf_1 panda pose 0: %d of %zu transitions (%.0f%%) collision-free-sampleable within %d "
              "tries; %d tries, %d satisfied the constraints; %.2f s\n",
              sampleable, g.transitions.size(), 100.0 * sampleable / g.transitions.size(), kTries, tries, ok_samples,
              seconds);
  RecordProperty("collision_free_sampleable_transitions", sampleable);
  RecordProperty("transitions", static_cast<int>(g.transitions.size()));
  std::set<int> feasible_picks;
  for (const auto& [key, bits] : ends_free)
    if (bits == 3) feasible_picks.insert(key.first);
  EXPECT_EQ(feasible_picks.size(), g.placement_sequence.size() - 1);
}
