#pragma once
// A kinematic tree read from URDF: links with their geometry, joints with limits.
// The model is constant; per-query results (link poses) live with the caller, as in Pinocchio.
#include <Eigen/Core>
#include <memory>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "core/geometry/se3.h"
#include "core/model/mesh.h"

namespace demoplan {

enum class JointType { Fixed, Revolute, Continuous, Prismatic };

struct JointLimits {
  double lower = 0.0;     // rad or m; -inf for continuous joints
  double upper = 0.0;     // rad or m; +inf for continuous joints
  double velocity = 0.0;  // rad/s or m/s; 0 when the URDF gives none
  double effort = 0.0;    // N m or N; 0 when the URDF gives none
};

// q[joint] = multiplier * q[mimicked] + offset, as the URDF writes it. The configuration keeps a
// slot for a mimic joint (the benchmark's convention); enforce_mimic() applies the relation.
struct Mimic {
  int joint = -1;  // index into RobotModel::joints
  double multiplier = 1.0;
  double offset = 0.0;
};

struct Joint {
  std::string name;
  JointType type = JointType::Fixed;
  int parent_link = -1;
  int child_link = -1;
  Pose origin = Pose::Identity();  // joint frame in the parent link frame
  Eigen::Vector3d axis = Eigen::Vector3d::UnitZ();  // unit, in the joint frame
  JointLimits limits;
  int q_index = -1;  // slot in the configuration vector; -1 for fixed joints
  std::optional<Mimic> mimic;
};

struct BoxShape {
  Eigen::Vector3d size;
};
struct CylinderShape {  // along z, centred
  double radius = 0.0;
  double length = 0.0;
};
struct SphereShape {
  double radius = 0.0;
};
struct MeshShape {
  std::string path;  // resolved, absolute
  Eigen::Vector3d scale = Eigen::Vector3d::Ones();
  std::shared_ptr<const TriangleMesh> mesh;  // null for a visual mesh that was not loaded
};
using Shape = std::variant<BoxShape, CylinderShape, SphereShape, MeshShape>;

struct Geometry {
  Shape shape;
  Pose origin = Pose::Identity();  // in the link frame
  Eigen::Vector4d color{0.7, 0.7, 0.7, 1.0};
};

struct Link {
  std::string name;
  int parent_joint = -1;  // -1 for the root link
  std::vector<int> child_joints;
  std::vector<Geometry> visuals;
  std::vector<Geometry> collisions;
};

struct RobotModel {
  std::string name;
  std::string urdf_path;
  std::vector<Link> links;    // links[0] is the root; every parent precedes its children
  std::vector<Joint> joints;  // depth-first order, children by joint name (urdfdom's order)
  int nq = 0;                 // number of non-fixed joints

  int link_index(const std::string& name) const;   // -1 when absent
  int joint_index(const std::string& name) const;  // -1 when absent
  // The non-fixed joints in configuration order.
  std::vector<const Joint*> configuration_joints() const;
  Eigen::VectorXd lower_limits() const;
  Eigen::VectorXd upper_limits() const;
  bool within_limits(const Eigen::VectorXd& q, double tol = 0.0) const;
  // Overwrites every mimic joint's slot from the joint it mimics.
  void enforce_mimic(Eigen::VectorXd& q) const;
  // Links rigidly connected through fixed joints share a body; bodies[i] is link i's body id,
  // the id of the topmost link of the rigid group.
  std::vector<int> rigid_bodies() const;
  // `link` and every link below it (a gripper's hand, fingers and what is mounted on them).
  std::vector<int> subtree_links(int link) const;
};

struct UrdfOptions {
  // Directories searched for package://NAME/... URIs: DIR/NAME/... must exist.
  std::vector<std::string> package_paths;
  // Visual meshes are only needed for drawing; collision meshes are always loaded.
  bool load_visual_meshes = false;
  MeshCache* mesh_cache = nullptr;  // optional; shares meshes across models
};

// Loads a URDF file. Relative mesh paths are resolved against the URDF's folder.
// Throws InputError naming the file and the element for anything malformed or missing.
RobotModel load_urdf(const std::string& path, const UrdfOptions& options = {});
// The same from text; source_path names the file in errors and anchors relative paths.
RobotModel parse_urdf(const std::string& xml, const std::string& source_path,
                      const UrdfOptions& options = {});

}  // namespace demoplan
