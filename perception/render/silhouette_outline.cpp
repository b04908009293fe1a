#include "perception/render/silhouette_outline.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <opencv2/imgproc.hpp>

#include "perception/render/rasterizer.h"

namespace demoplan::perception {

namespace {

constexpr double kNear = 0.05;  // m, as the rasterizer clips
constexpr int kMargin = 2;      // px around the part's box, so its silhouette never touches the window's edge

// The part's box in the image, clamped to it; the whole image when part of the mesh is behind
// the near plane (its projection is unbounded there).
cv::Rect image_box(const RenderMesh& mesh, const Pose& camera_T_mesh, const Camera& camera) {
  const cv::Rect image(0, 0, camera.image_size.width, camera.image_size.height);
  double x0 = std::numeric_limits<double>::infinity(), y0 = x0, x1 = -x0, y1 = -x0;
  for (const auto& v : mesh.vertices) {
    const Eigen::Vector3d p = camera_T_mesh * v.cast<double>();
    if (p.z() < kNear) return image;
    const double x = camera.fx * p.x() / p.z() + camera.cx, y = camera.fy * p.y() / p.z() + camera.cy;
    x0 = std::min(x0, x), x1 = std::max(x1, x), y0 = std::min(y0, y), y1 = std::max(y1, y);
  }
  if (!(x0 <= x1)) return {};
  // Far outside the image the doubles would overflow an int: clamp first.
  auto clamp = [](double v, int hi) { return int(std::clamp(v, -1.0, double(hi) + 1)); };
  const cv::Rect box(cv::Point(clamp(std::floor(x0), image.width) - kMargin, clamp(std::floor(y0), image.height) - kMargin),
                     cv::Point(clamp(std::ceil(x1), image.width) + kMargin + 1, clamp(std::ceil(y1), image.height) + kMargin + 1));
  return box & image;
}

}  // namespace

std::vector<std::vector<cv::Point2f>> silhouette_outline(const RenderMesh& mesh, const Pose& world_T_mesh,
                                                         const Camera& camera) {
  std::vector<std::vector<cv::Point2f>> out;
  if (!camera.world_T_camera || mesh.triangles.empty()) return out;
  const Pose camera_T_mesh = camera.world_T_camera->inverse() * world_T_mesh;
  const cv::Rect box = image_box(mesh, camera_T_mesh, camera);
  if (box.width < 1 || box.height < 1) return out;
  // The window's own camera: the same one with its principal point moved to the window.
  Rasterizer r(box.size(), camera.fx, camera.fy, camera.cx - box.x, camera.cy - box.y, *camera.world_T_camera);
  r.clear({0, 0, 0}, {0, 0, 0});
  r.draw(mesh, world_T_mesh);
  std::vector<std::vector<cv::Point>> contours;
  cv::findContours(cv::Mat(r.depth() < 1e9f), contours, cv::RETR_EXTERNAL, cv::CHAIN_APPROX_SIMPLE);

  const int w = camera.image_size.width, h = camera.image_size.height;
  auto on_border = [&](const cv::Point& p, int side) {
    return side == 0 ? p.x == 0 : side == 1 ? p.y == 0 : side == 2 ? p.x == w - 1 : p.y == h - 1;
  };
  auto along_border = [&](const cv::Point& a, const cv::Point& b) {
    for (int side = 0; side < 4; ++side)
      if (on_border(a, side) && on_border(b, side)) return true;
    return false;
  };
  const bool distorted = !camera.distortion.empty();
  auto to_image = [&](const cv::Point& p) {
    if (!distorted) return cv::Point2f(float(p.x), float(p.y));
    // The rasterizer draws an ideal pinhole image: bend its points as the lens does.
    const cv::Point2d d = camera.project({(p.x - camera.cx) / camera.fx, (p.y - camera.cy) / camera.fy, 1.0});
    return cv::Point2f(float(d.x), float(d.y));
  };
  for (auto& contour : contours) {
    for (auto& p : contour) p += box.tl();
    const size_t n = contour.size();
    if (n < 2) continue;
    // Start the walk just after a cut along the border, if there is one, so each piece is whole.
    size_t start = 0;
    for (size_t i = 0; i < n; ++i)
      if (along_border(contour[i], contour[(i + 1) % n])) {
        start = (i + 1) % n;
        break;
      }
    std::vector<cv::Point2f> piece{to_image(contour[start])};
    for (size_t k = 0; k < n; ++k) {
      const cv::Point& a = contour[(start + k) % n];
      const cv::Point& b = contour[(start + k + 1) % n];
      if (along_border(a, b)) {
        if (piece.size() > 1) out.push_back(std::move(piece));
        piece = {to_image(b)};
      } else {
        piece.push_back(to_image(b));
      }
    }
    if (piece.size() > 1) out.push_back(std::move(piece));
  }
  return out;
}

}  // namespace demoplan::perception
