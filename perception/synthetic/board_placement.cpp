#include "perception/synthetic/board_placement.h"

#include "perception/synthetic/camera_placement.h"

#include <cmath>

#include <opencv2/imgproc.hpp>

namespace demoplan::perception {

std::optional<MarkerBoard> place_board(const DemoScript& s, const Pose& table_top, const Eigen::Vector2d& table_size,
                                       const Camera& camera, const std::vector<Eigen::AlignedBox3d>& obstacles,
                                       MarkerBoard board) {
  // Where parts are near the table top, as boxes in the table frame.
  const Pose top_T_world = table_top.inverse();
  std::vector<Eigen::AlignedBox2d> busy;
  for (int f = 0; f < s.frames; f += 2)
    for (size_t k = 0; k < s.object_ids.size(); ++k) {
      Eigen::AlignedBox3d b;
      for (int c = 0; c < 8; ++c)
        b.extend(top_T_world * (s.poses[f][k] * s.bounds[k].corner(static_cast<Eigen::AlignedBox3d::CornerType>(c))));
      if (b.min().z() > 0.5) continue;
      busy.emplace_back(b.min().head<2>() - Eigen::Vector2d::Constant(0.04), b.max().head<2>() + Eigen::Vector2d::Constant(0.04));
    }
  // Furniture standing on the top (a fixture, a shelf on a table): the board does not go under it.
  for (const auto& box : obstacles) {
    Eigen::AlignedBox3d b;
    for (int c = 0; c < 8; ++c) b.extend(top_T_world * box.corner(static_cast<Eigen::AlignedBox3d::CornerType>(c)));
    if (b.max().z() > 0.005 && b.min().z() < 0.5)
      busy.emplace_back(b.min().head<2>() - Eigen::Vector2d::Constant(0.02), b.max().head<2>() + Eigen::Vector2d::Constant(0.02));
  }
  for (const auto& h : s.hand) {
    const Eigen::Vector3d p = top_T_world * h.translation();
    if (p.z() < 0.5) busy.emplace_back(p.head<2>() - Eigen::Vector2d::Constant(0.12), p.head<2>() + Eigen::Vector2d::Constant(0.12));
  }
  const Pose camera_T_world = camera.world_T_camera->inverse();
  // The board's extent in its own frame, as OpenCV lays it out.
  Eigen::AlignedBox2d extent;
  const auto grid = board.make();
  for (const auto& marker : grid->objPoints)
    for (const auto& c : marker) extent.extend(Eigen::Vector2d(c.x, c.y));
  const double w = extent.sizes().x(), h = extent.sizes().y();
  double best_area = 0;
  std::optional<MarkerBoard> best;
  for (double x = -table_size.x() / 2 + 0.03; x + w <= table_size.x() / 2 - 0.03; x += 0.025)
    for (double y = -table_size.y() / 2 + 0.03; y + h <= table_size.y() / 2 - 0.03; y += 0.025) {
      const Eigen::AlignedBox2d rect(Eigen::Vector2d(x, y), Eigen::Vector2d(x + w, y + h));
      bool free = true;
      for (const auto& b : busy)
        if (b.intersects(rect)) {
          free = false;
          break;
        }
      if (!free) continue;
      std::vector<cv::Point2f> corners;
      bool visible = true;
      // Nothing may hide any of a 3x3 grid of points on the board.
      for (int g = 0; g < 9 && visible; ++g) {
        const Eigen::Vector3d world = table_top * Eigen::Vector3d(x + w * (g % 3) / 2, y + h * (g / 3) / 2, 0.01);
        for (const auto& box : obstacles)
          if (!box.contains(world) && segment_hits_box(camera.world_T_camera->translation(), world, box)) visible = false;
      }
      for (int c = 0; c < 4; ++c) {
        const Eigen::Vector3d world = table_top * Eigen::Vector3d(c & 1 ? x + w : x, c & 2 ? y + h : y, 0.01);
        const Eigen::Vector3d p = camera_T_world * world;
        if (p.z() < 0.3) { visible = false; break; }
        const cv::Point2d q = camera.project(p);
        if (q.x < 40 || q.y < 40 || q.x > camera.image_size.width - 40 || q.y > camera.image_size.height - 40) visible = false;
        corners.emplace_back(static_cast<float>(q.x), static_cast<float>(q.y));
      }
      if (!visible) continue;
      std::swap(corners[2], corners[3]);  // polygon order
      const double area = std::abs(cv::contourArea(corners));
      if (area > best_area) {
        best_area = area;
        // Face up: OpenCV's board z points into the board, so it points down into the table.
        board.world_T_board = table_top * Eigen::AngleAxisd(M_PI, Eigen::Vector3d::UnitX());
        board.world_T_board.translation() =
            table_top * Eigen::Vector3d(x - extent.min().x(), y + h + extent.min().y(), 0.0005);
        best = board;
      }
    }
  return best;
}

}  // namespace demoplan::perception
