#pragma once
// A planned path: waypoints joined by straight joint-space segments. Each waypoint carries the
// robot configuration, every object's world pose, the constraint-graph state it lies in and
// the gripper action that starts at it.
#include <string>
#include <vector>

#include "core/scene/scene.h"

namespace demoplan {

enum class GripperAction { None, Grasp, Release };

struct Waypoint {
  Eigen::VectorXd q;
  PoseList objects;        // world pose of every object (Scene::objects order)
  int state = -1;          // index into the constraint graph's states
  std::string state_name;  // e.g. "P1", "G0 YCBV_05/handleXpy"
  GripperAction action = GripperAction::None;  // closes (grasp) or opens (release) here
  int object = -1;         // the object grasped or released, for an action
  // The segment to the next waypoint is a straight approach or retreat along a handle's axis
  // (part of a transition): shortcutting keeps it.
  bool approach = false;
};

struct Path {
  std::string task;   // e.g. "shelf_1"
  std::string robot;  // e.g. "panda"
  int robot_pose = 0;
  std::vector<std::string> joint_names;  // configuration order
  std::vector<std::string> object_ids;
  std::vector<Waypoint> waypoints;

  // Sum of the joint-space lengths of the segments (rad, and m for prismatic joints).
  double robot_length() const;
};

// JSON {"format": "demoplan-path", "version": 1, ...}; object poses as 4x4 row-major world
// transforms in metres; configurations in radians and metres. Saving is atomic; loading
// throws InputError naming the file and field.
void save_path(const std::string& file, const Path& path);
Path load_path(const std::string& file);

}  // namespace demoplan
