#pragma once
// Which ArUco markers are stuck on which parts, and where: what the tracker needs to turn a
// marker seen in the image into the pose of a part.
//
// File "demoplan-marker-scene" version 1 (JSON):
//   {"format": "demoplan-marker-scene", "version": 1,
//    "task": "shelf_1", "robot": "panda", "robot_pose": 0,   // the benchmark scene it shows
//    "cell": "../cells/ur5_workbench.json",                   // or the cell it shows (optional,
//                                                             // relative to this file)
//    "camera": "camera.json",                                 // relative to this file
//    "dictionary": "DICT_4X4_100",
//    "objects": [{"id": "YCBV_02", "planning": true,
//                 "markers": [{"id": 0, "size": 0.06,
//                              "object_T_marker": {"t": [x, y, z], "q": [qx, qy, qz, qw]}}]}]}
// object_T_marker is the marker frame in the object frame (metres): OpenCV's marker frame,
// origin at the marker centre, z out of the printed face, x to the right and y up in the
// printed image. `size` is the side of the black square (metres). A marker id belongs to one
// object only. "planning": false marks a part that is tracked but not planned for (a tray).
// An object may be given as a box instead of by a model of the task or cell (a tray or a board
// the demonstrator moves, which the task has no model of):
//    "box": {"size": [x, y, z], "rgb": [r, g, b]}   // metres, centred on the part's origin; 0..255
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "core/geometry/se3.h"

namespace demoplan::perception {

struct ObjectMarker {
  int id = 0;
  double size = 0.05;
  Pose object_T_marker = Pose::Identity();
};

struct MarkedObject {
  std::string id;
  bool planning = true;
  std::vector<ObjectMarker> markers;
  std::optional<Eigen::Vector3d> box;        // size (m): the part is this box, not a model
  Eigen::Vector3i box_rgb{128, 128, 128};    // its colour
};

struct MarkerScene {
  std::string task;
  std::string robot;
  int robot_pose = 0;
  std::string cell;    // path of the cell file, as written (relative to the scene file); "" none
  std::string camera;  // path of the camera file, as written (relative to the scene file)
  std::string dictionary = "DICT_4X4_100";
  std::vector<MarkedObject> objects;

  // Object and marker index of a marker id; false when no object carries it.
  bool find_marker(int id, int& object, int& marker) const;
  std::vector<std::string> planning_object_ids() const;
};

// The part's box when it is given as one, else the box spanned by its markers in its frame (a
// 10 cm cube at the origin without markers): the part's extent where no model is at hand.
Eigen::AlignedBox3d marker_extent(const MarkedObject& object);

// Throws InputError for malformed files, unknown dictionaries, duplicate marker ids.
MarkerScene load_marker_scene(const std::string& path);
void save_marker_scene(const std::string& path, const MarkerScene& scene);

}  // namespace demoplan::perception
