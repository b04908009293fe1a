#pragma once
// An ArUco grid board (markers_x by markers_y markers) lying at a known pose in the world, e.g.
// flat on the table: seen by the camera, it gives the camera's pose in the world.
// Board frame (OpenCV 4.6's GridBoard): origin at the top-left corner of marker first_id, x to
// the right along the first row, y down the printed page towards the next rows, z into the
// board (so z points down when the board lies face up on a table).
#include <string>

#include <opencv2/aruco.hpp>

#include "core/geometry/se3.h"

namespace demoplan::perception {

struct MarkerBoard {
  std::string dictionary = "DICT_4X4_100";
  int markers_x = 4, markers_y = 3;
  double marker_length = 0.08;      // m, black square side
  double marker_separation = 0.02;  // m, between neighbouring markers
  int first_id = 80;                // ids first_id .. first_id + markers_x * markers_y - 1
  Pose world_T_board = Pose::Identity();

  double width() const { return markers_x * marker_length + (markers_x - 1) * marker_separation; }
  double height() const { return markers_y * marker_length + (markers_y - 1) * marker_separation; }
  int marker_count() const { return markers_x * markers_y; }
  bool owns(int id) const { return id >= first_id && id < first_id + marker_count(); }
  cv::Ptr<cv::aruco::GridBoard> make() const;
};

}  // namespace demoplan::perception
