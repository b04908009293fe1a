#pragma once
// The choreography of a synthetic demonstration video: where every part, the hand and the tray
// are at every frame. Parts rest at the task's subgoal key poses and are carried between a grasp
// and its release along a smooth lifted path; the hand approaches each part from behind it (seen
// from the camera), carries it and moves on. The ground truth follows from the same data.
//
// Frame conventions of the truth: a grasp's frame is the last frame at which the part is still
// at rest (the hand holds it, the lift starts after it); a release's frame is the first frame
// at which the part is at rest again.
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "core/demo/benchmark_task.h"
#include "core/demo/demonstration.h"

namespace demoplan::perception {

struct ScriptCarry {
  int object = -1;  // index into DemoScript::object_ids
  int grasp = 0, release = 0;
};

// Parts that ride on a tray the demonstrator carries (waiter): they move together, no grasp.
// A transport is made when parts not grasped in between sit, on average, more than 25 cm
// elsewhere at the next grasp's key pose and there are 12 frames or more for the ride.
struct ScriptTransport {
  std::vector<int> objects;
  int start = 0, end = 0;  // first and last frame of the motion
};

struct DemoScript {
  std::string task;
  double fps = 30.0;
  int frames = 0;
  std::vector<std::string> object_ids;      // the task's planning objects
  std::vector<Eigen::AlignedBox3d> bounds;  // per object, in its frame
  std::vector<PoseList> poses;              // [frame][object], world
  std::vector<ScriptCarry> carries;         // sorted by grasp frame
  std::vector<ScriptTransport> transports;
  std::vector<std::optional<Pose>> tray;    // [frame] top-centre of the tray, when there is one
  Eigen::Vector3d tray_size = Eigen::Vector3d::Zero();
  std::vector<Pose> hand;                   // [frame] palm frame (see hand_model.h); after add_hand

  // Events at the carries' grasp and release frames with every part's pose there.
  Demonstration truth() const;
};

// Builds the motion of the parts and the tray from the task's contact segments and subgoal
// columns; `time_scale` < 1 makes a shorter video (every frame index scaled). Throws
// InputError when the task has no subgoals.
DemoScript make_demo_script(const BenchmarkTask& task, const std::vector<Eigen::AlignedBox3d>& object_bounds,
                            double time_scale = 1.0);

// The motion of a demonstration given as its events (a cell's picks, cell_picks.h): every part
// rests at its pose in the events, and is carried from each grasp of it to the next release of it
// along carry_pose. `start` holds every part's pose before the first event; `tail` frames follow
// the last release. Throws InputError when the events do not pair up per part.
DemoScript make_demo_script(const Demonstration& truth, const PoseList& start,
                            const std::vector<Eigen::AlignedBox3d>& object_bounds, int tail = 30);

// Adds the hand: attached behind the part it carries (as seen from `camera_position`), or
// behind the tray during a transport, and moving between them in between.
void add_hand(DemoScript& script, const Eigen::Vector3d& camera_position);

// The smooth lifted path of a carry at normalised time t in [0, 1] (exactly A at 0, B at 1).
Pose carry_pose(const Pose& A, const Pose& B, double t, double clearance = 0.15);

}  // namespace demoplan::perception
