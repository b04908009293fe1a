#pragma once
// A free spot on the table top for the ArUco board that gives the camera's extrinsics: inside
// the top, clear of every place a part rests or passes and of furniture standing on it, seen
// large by the camera.
#include <optional>

#include <Eigen/Geometry>

#include "perception/camera/camera_model.h"
#include "perception/synthetic/demo_script.h"

namespace demoplan::perception {

// `obstacles`: furniture boxes that must not hide the board from the camera.
// `table_top`: world pose of the centre of the table's top surface (z up); `table_size`: its
// extent along the frame's x and y. Returns `board` with world_T_board set, or nullopt.
std::optional<MarkerBoard> place_board(const DemoScript& script, const Pose& table_top,
                                       const Eigen::Vector2d& table_size, const Camera& camera,
                                       const std::vector<Eigen::AlignedBox3d>& obstacles, MarkerBoard board);

}  // namespace demoplan::perception
