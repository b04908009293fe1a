#pragma once
// Grasp handles for a parallel-jaw gripper from a part's mesh alone: closing lines whose two
// outermost contacts face each other within the friction cone and fit the opening, approached
// from directions in which the open hand stays out of the part (FCL against the hand's
// collision geometry), each pushed as deep into the hand as the palm allows and also held
// shallower in 15 mm steps (an arm that cannot reach deep may reach these), then clustered into
// distinct handles, the best first. They are the benchmark SRDF's kind of handle (x: the
// approach, z: the closing direction, clearance: the opening they need), so the planner takes
// them as it takes hand-made ones.
//
// Candidate lines are structured, not random: closing directions along the part's axes, their
// 45-degree diagonals and its largest flat faces' normals; approach directions every 45 degrees
// about each, starting from a part axis; lines through the centre of mass and beside it. A CAD
// part (or a BOP model) is drawn in a frame that means something, and grasps along it are the
// ones a person would choose. Deterministic: no random numbers.
#include <string>
#include <vector>

#include "core/model/mesh.h"
#include "core/model/robot_model.h"
#include "core/model/srdf.h"
#include "core/scene/scene.h"

namespace demoplan {

// The hand as the generator sees it: its collision shapes with the fingers open, each shape's
// origin its pose in the gripper frame (SRDF <gripper>), and how far the fingers open.
struct ParallelGripper {
  std::vector<Geometry> hand;
  double opening = 0.08;  // m
};

// The gripper of a robot: srdf.grippers[0] on its link; the hand is that link and every link
// below it, the movable joints below it (the fingers) at their upper limits. Throws InputError
// naming the SRDF when the gripper or its link is missing.
ParallelGripper parallel_gripper(const RobotModel& model, const Srdf& srdf);

struct GraspOptions {
  double friction_angle = 0.26;    // rad (15 deg): contact normals this close to the closing line
  double approach_step = 0.7853981633974483;  // rad between approach directions about a closing line
  double lateral_step = 0.02;      // m between closing lines side by side, across the fingers
  double depth_step = 0.01;        // m: coarse step of the depth search (refined by bisection)
  double depth_tolerance = 0.001;  // m: resolution of the depth search
  double palm_clearance = 0.005;   // m left between part and hand at the deepest grasp
  double depth_variant_step = 0.015;  // m between the deepest grasp and shallower ones ...
  double min_engagement = 0.015;      // m: ... as long as this much of the part is between the fingers
  double width_margin = 0.002;     // m: each finger's travel left when it touches
  double min_width = 0.004;        // m: thinner features are not grasped
  double cluster_distance = 0.015;  // m: handles closer than this ...
  double cluster_angle = 0.25;     // rad (14 deg): ... and turned less than this are one handle
  int max_handles = 48;
};

struct GeneratedHandle {
  GraspFrame frame;      // pose in the part frame; clearance: the opening it needs
  double quality = 0.0;  // 0..1: antipodality, fingers across the centre of mass, flat contacts, depth
  double width = 0.0;    // m between the two contacts
};

struct GraspReport {
  std::vector<GeneratedHandle> handles;  // the best first
  int closing_lines = 0;    // lines tried
  int fitting_lines = 0;    // of them antipodal and within the opening
  int hand_checks = 0;      // FCL queries of the hand against the part
  int candidates = 0;       // grasps found before clustering
  double seconds = 0.0;
  std::string why_none;     // when there is no handle: why, in the user's terms
};

// Handles for the part `mesh` (its units times `scale` are metres; the part frame is the
// mesh's) whose centre of mass is `com`, on link `link`, named "<prefix><k>".
GraspReport generate_handles(const TriangleMesh& mesh, double scale, const Eigen::Vector3d& com,
                             const ParallelGripper& gripper, const GraspOptions& options = {},
                             const std::string& link = "base_link", const std::string& prefix = "grasp_");

// Whether a generated handle stands for a hand-made one: within 1 cm and 15 degrees (the
// rotation between the two frames), the rule by which the generator is measured (issue 15).
bool handle_matches(const Pose& generated, const Pose& hand_made);

// Replaces the handles of a scene's object (its first collision mesh is the part) by generated
// ones: the generator measured against hand-made handles on the benchmark. Returns the report;
// throws InputError naming the object's SRDF when it has no mesh or no handle is found.
GraspReport use_generated_handles(SceneObject& object, const ParallelGripper& gripper, const GraspOptions& options = {});

}  // namespace demoplan
