#pragma once
// The admissible configuration space built from a demonstration (Sec. III-B of the paper):
// placement states P_0..P_K where every object rests at a demonstrated pose, and between two
// consecutive placements the grasp states, one per handle of the object that moves, where that
// object is held by the gripper and the others stay put. A configuration is the robot's q;
// object poses follow from the state.
#include <string>
#include <vector>

#include "core/demo/demonstration.h"
#include "core/scene/scene.h"

namespace demoplan {

// Where an object rests: a world pose, or a pose relative to a robot link when it rests on
// a surface of the robot (the KMR's deck) and travels with it.
struct ObjectPlacement {
  int link = -1;  // robot link, -1 for the world
  Pose pose = Pose::Identity();
};

enum class StateKind { Placement, Grasp };

struct GraphState {
  StateKind kind = StateKind::Placement;
  std::string name;                      // "P0", "G0 YCBV_05/handleZpx"
  std::vector<ObjectPlacement> objects;  // every object; a grasp state's held object: unused
  int object = -1;                       // grasp states: the held object
  int handle = -1;                       // grasp states: index into the object's SRDF handles
  int step = -1;                         // placement: its position in the demo; grasp: the pick k
};

enum class TransitionKind { Grasp, Release };

// Placement -> grasp goes through a pre-grasp waypoint (gripper backed off the handle along
// its approach axis by the handle's clearance) and reaches the handle along that axis; grasp ->
// placement releases and backs off the same way. `sample_on_transition` returns the two ends
// of that straight move: (pre-grasp, grasp) or (release, retreat).
struct GraphTransition {
  TransitionKind kind = TransitionKind::Grasp;
  int from = -1, to = -1;  // states
  int object = -1, handle = -1;
  std::string name;
  // The state the approach/retreat move itself belongs to: the placement state (the object
  // is still, or again, resting while the gripper moves along the axis).
  int edge_state() const { return kind == TransitionKind::Grasp ? from : to; }
};

// Pick k of the demonstration in the graph: the placements before and after it, and its grasp
// states (one per handle of the moved object the gripper can open around), each with the
// transition into it and the one out of it.
struct GraphPick {
  int object = -1;
  int from = -1, to = -1;         // placement states
  std::vector<int> grasp_states;  // states
  std::vector<int> grasp, release;  // transitions, parallel to grasp_states
};

struct ConstraintGraph {
  std::vector<GraphState> states;
  std::vector<GraphTransition> transitions;
  std::vector<int> placement_sequence;  // placement states in demonstration order
  std::vector<GraphPick> picks;         // in demonstration order
  int start_state = -1, goal_state = -1;
  Eigen::VectorXd q_start, q_goal;
  // Joints moved to reach a handle (all but the gripper's own), and the gripper's own joints,
  // held open in grasp states so the fingers clear the part (handle clearance <= opening).
  std::vector<int> reach_joints, gripper_joints;
  Eigen::VectorXd gripper_open;  // value of each gripper joint when open

  std::vector<int> states_of_kind(StateKind kind) const;
};

// Two placements are the same when every object is within these of its pose in the other.
struct GraphOptions {
  double same_position = 1e-3;  // m
  double same_rotation = 1e-3;  // rad
};

// Whether every object rests at the same place in both (within the options' tolerances).
bool same_placements(const std::vector<ObjectPlacement>& a, const std::vector<ObjectPlacement>& b,
                     const GraphOptions& options = {});

// Builds the graph for the scene's robot. The demonstration's objects must be the scene's
// objects in the same order. Throws InputError naming the rule when the demonstration is invalid.
ConstraintGraph build_constraint_graph(const Scene& scene, const Demonstration& demo,
                                       const GraphOptions& options = {});

// The scene at configuration q of a state: every object's world pose, held and travelling
// objects as attachments to their robot link.
SceneState scene_state(const Scene& scene, const ConstraintGraph& graph, int state,
                       const Eigen::VectorXd& q);

// Transform from the gripper link to a held object: the gripper frame coincides with the handle.
Pose gripper_link_T_object(const Scene& scene, int object, int handle);

}  // namespace demoplan
