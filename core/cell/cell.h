#pragma once
// A robot cell the user builds from files: a robot at its base pose, furniture, the parts the
// task moves. One versioned JSON file, documented field by field in docs/cell.md:
//
// {"format": "demoplan-cell", "version": 1, "name": "ur5 workbench",
//  "package_paths": ["models"],                       // searched for package://NAME/... URIs
//  "robot": {"bundled": "ur5"}                        // or {"urdf": ..., "srdf": ...,
//           + "base": {"xyz": [0, 0, 0.9], "rpy": [0, 0, 0]},   //     "mobile": false,
//             "initial_configuration": [...]},                  //     "initial_configuration"}
//  "furniture": [{"name": "bench", "box": [1.2, 0.8, 0.9],      // or "cylinder": {"radius",
//                 "pose": {...}, "supports": "auto"}],          // "length"}, "mesh" + "scale",
//                                                               // "urdf" (+ "srdf")
//  "parts": [{"name": "bracket", "mesh": "bracket.stl", "scale": 0.001,
//             "pose": {...},                                    // where it is at the start
//             "contacts": "auto" | [[[x, y, z], ...], ...],     // polygons, part frame
//             "handles": "auto" | [{"name", "pose", "clearance"}],
//             "markers": [{"id": 3, "size": 0.03, "pose": {...}}]}],
//  "marker_dictionary": "DICT_4X4_100",
//  "grasping": {"palm_clearance": 0.005, "max_handles": 48}}
// Poses are {"xyz": [m], "rpy": [rad]} (URDF's roll-pitch-yaw), both optional. Furniture
// poses place the shape's centre (box, cylinder) or its file's origin (mesh, URDF) in the world.
// File paths are relative to the cell file and held absolute in memory. "auto" supports are the
// upward faces of the furniture (support_surfaces.h); "auto" contacts are the part's resting
// placements (resting_placements.h); "auto" handles are generated for the robot's gripper
// (grasp_handles.h).
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "core/geometry/se3.h"
#include "core/io/json_file.h"
#include "core/model/srdf.h"

namespace demoplan {

inline constexpr const char* kCellFormat = "demoplan-cell";
inline constexpr int kCellVersion = 1;

using Polygon3 = std::vector<Eigen::Vector3d>;

struct CellRobot {
  std::string bundled;     // a robot of the bundled robots.json (panda, ur5, kuka_iiwa, ...), or ""
  std::string urdf, srdf;  // absolute; used when not bundled
  bool mobile = false;     // a mobile base moves through joints of its own
  Eigen::VectorXd initial_configuration;  // empty: the bundled robot's, else zeros within the limits
  Pose base = Pose::Identity();
};

struct CellFurniture {
  enum class Kind { Box, Cylinder, Mesh, Urdf };
  std::string name;
  Kind kind = Kind::Box;
  Eigen::Vector3d box = Eigen::Vector3d::Zero();  // m
  double radius = 0.0, length = 0.0;              // m, cylinder along its z
  std::string file;  // mesh or URDF, absolute
  std::string srdf;  // URDF furniture: its SRDF with <contact> surfaces, absolute; "" none
  double scale = 1.0;  // metres per mesh unit
  Pose pose = Pose::Identity();
  bool auto_supports = true;
  std::vector<Polygon3> supports;  // furniture frame, when not auto
  double min_support_area = 0.01;  // m^2: smaller upward faces are not supports
  Eigen::Vector4d color{0.62, 0.55, 0.45, 1.0};
};

struct CellMarker {
  int id = 0;
  double size = 0.03;  // m, black square side
  Pose pose = Pose::Identity();  // marker frame in the part frame (OpenCV's: z out of the face)
};

struct CellPart {
  std::string name;
  std::string mesh;  // absolute
  double scale = 1.0;
  Pose pose = Pose::Identity();  // world pose at the start
  bool auto_contacts = true;
  std::vector<Polygon3> contacts;  // part frame, when not auto
  bool auto_handles = true;
  std::vector<GraspFrame> handles;  // part frame (link "base_link"), when not auto
  std::vector<CellMarker> markers;
  Eigen::Vector4d color{0.75, 0.75, 0.78, 1.0};
};

struct CellGrasping {
  double palm_clearance = 0.005;  // m
  int max_handles = 48;
};

struct Cell {
  std::string file;  // absolute path it was read from or will be written to
  std::string name;
  std::vector<std::string> package_paths;  // absolute
  CellRobot robot;
  std::vector<CellFurniture> furniture;
  std::vector<CellPart> parts;
  std::string marker_dictionary = "DICT_4X4_100";
  CellGrasping grasping;

  int part_index(const std::string& name) const;  // -1 when absent
};

// Reads and writes the cell file. Loading throws InputError naming the file and the field
// (duplicate names, unknown shapes, a non-positive size or scale, both "bundled" and "urdf").
// Files it names are checked when the scene is built (cell_scene.h), not here.
Cell load_cell(const std::string& file);
void save_cell(const std::string& file, const Cell& cell);
Json cell_to_json(const Cell& cell, const std::string& file);
Cell cell_from_json(const Json& json, const std::string& file);

}  // namespace demoplan
