#pragma once
// The world a task happens in: one robot at its base pose, fixed furniture, movable objects.
// Scene is constant during planning; SceneState is one configuration of it.
#include <Eigen/Core>
#include <string>
#include <utility>
#include <vector>

#include "core/geometry/se3.h"
#include "core/model/kinematics.h"
#include "core/model/robot_model.h"
#include "core/model/srdf.h"

namespace demoplan {

struct SceneRobot {
  std::string name;  // benchmark name: panda, ur5, kmr_iiwa, ...
  RobotModel model;
  Srdf srdf;
  Pose base = Pose::Identity();  // world pose of the root link
  // A fixed robot's root link is attached to the world like the furniture; a mobile robot
  // moves through joints of its own (the KMR's x, y, theta).
  bool fixed_base = true;
  Eigen::VectorXd initial_configuration;
  int gripper_link = -1;  // link of srdf.grippers[0]

  const GraspFrame& gripper() const { return srdf.grippers.front(); }
};

struct SceneFurniture {
  std::string name;  // e.g. "shelf_1_1_shelf"
  std::string kind;  // table, shelf, tunnel, box
  RobotModel model;  // all joints fixed; the URDF carries the world pose
  Srdf srdf;
  PoseVector link_poses;  // world pose of every link
  // Links the robot never collides with (the tunnel's closing walls, see gtamp README 6).
  std::vector<std::string> robot_ignored_links;
};

struct SceneObject {
  std::string id;          // as the task names it, e.g. YCBV_02
  std::string model_name;  // e.g. obj_000002
  RobotModel model;        // the object's pose is the world pose of its root link
  Srdf srdf;
};

struct Scene {
  std::string name;  // task instance, e.g. "shelf_1 panda pose 0"
  SceneRobot robot;
  std::vector<SceneFurniture> furniture;
  std::vector<SceneObject> objects;

  int object_index(const std::string& id) const;  // -1 when absent
};

// An object held rigidly by a robot link: its pose follows the link.
struct Attachment {
  int object = -1;
  int link = -1;
  Pose link_T_object = Pose::Identity();
};

using PoseList = std::vector<Pose, Eigen::aligned_allocator<Pose>>;

struct SceneState {
  Eigen::VectorXd q;     // robot configuration
  PoseList objects;      // world pose of every object, in Scene::objects order
  std::vector<Attachment> attachments;
};

// Recomputes the pose of every attached object from the robot's link poses.
void update_attached_objects(const PoseVector& robot_link_poses, SceneState& state);
// World pose of the robot's gripper frame.
Pose gripper_pose(const Scene& scene, const Eigen::VectorXd& q);
// Attaches an object to the gripper link where it is now (relative pose kept).
Attachment attach_to_gripper(const Scene& scene, const SceneState& state, int object);

// Every collision mesh of the robot, the objects and the furniture, with its scale.
std::vector<std::pair<const TriangleMesh*, Eigen::Vector3d>> collision_meshes(const Scene& scene);

}  // namespace demoplan
