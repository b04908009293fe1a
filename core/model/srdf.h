#pragma once
// SRDF as the benchmark writes it (HPP conventions): grippers, handles, contact surfaces and
// disabled collision pairs. Positions are "x y z qw qx qy qz" (scalar first).
#include <Eigen/Core>
#include <string>
#include <vector>

#include "core/geometry/se3.h"

namespace demoplan {

// A frame on a robot link (gripper) or an object link (handle). Its x-axis is the approach
// direction and z the closing direction. Clearance is the opening (gripper) or the width the
// gripper must open to (handle), in metres.
struct GraspFrame {
  std::string name;
  std::string link;
  Pose pose = Pose::Identity();  // in the link frame
  double clearance = 0.0;
};

// Polygons on a link where objects may rest (furniture, robot) or that rest (objects).
struct ContactSurface {
  std::string name;
  std::string link;
  std::vector<Eigen::Vector3d> points;    // in the link frame
  std::vector<std::vector<int>> polygons;  // indices into points
  // The polygons as vertex lists, in the link frame.
  std::vector<std::vector<Eigen::Vector3d>> polygon_vertices() const;
};

struct Srdf {
  std::string robot_name;
  std::string path;
  std::vector<GraspFrame> grippers;
  std::vector<GraspFrame> handles;
  std::vector<ContactSurface> contacts;
  std::vector<std::pair<std::string, std::string>> disabled_collisions;

  const GraspFrame* gripper(const std::string& name) const;
  const GraspFrame* handle(const std::string& name) const;
  bool collision_disabled(const std::string& link1, const std::string& link2) const;
};

// Throws InputError naming the file, the element and what is wrong.
Srdf load_srdf(const std::string& path);
Srdf parse_srdf(const std::string& xml, const std::string& source_path);

}  // namespace demoplan
