#pragma once
// A small software renderer for synthetic test videos: z-buffered triangles with perspective-
// correct texture sampling and flat diffuse shading, plus anti-aliased planar markers. Pixel
// centres are at integer coordinates, as in OpenCV. Pinhole camera without distortion.
#include <optional>

#include <Eigen/Core>
#include <opencv2/core.hpp>

#include "core/geometry/se3.h"
#include "perception/render/render_mesh.h"

namespace demoplan::perception {

class Rasterizer {
public:
  Rasterizer(cv::Size size, double fx, double fy, double cx, double cy, const Pose& world_T_camera);

  // Background: a vertical gradient; depth: infinitely far.
  void clear(const cv::Vec3b& top, const cv::Vec3b& bottom);
  // Starts from a previously rendered image and depth (e.g. the static part of the scene); an
  // empty `color` leaves the image as it is (for depth-only drawing).
  void restore(const cv::Mat& color, const cv::Mat& depth);

  void draw(const RenderMesh& mesh, const Pose& world_T_mesh);
  // The same depth as draw, without shading or colour (an occlusion map asks for it several
  // times a frame): each vertex is projected once, not once per triangle. Where `labels`
  // (CV_8U, the image's size) is given, the pixels the mesh comes nearest in are set to `label`.
  void draw_depth(const RenderMesh& mesh, const Pose& world_T_mesh, cv::Mat* labels = nullptr, uchar label = 0);
  // A square marker image (8-bit grey, with its white margin) drawn as a square of side
  // `side` metres centred on the marker frame's origin in its x-y plane, image top towards +y.
  // Seen from behind, it is not drawn. Edges are anti-aliased (4x4 samples per pixel).
  void draw_marker(const cv::Mat& image, double side, const Pose& world_T_marker);

  const cv::Mat& color() const { return color_; }  // CV_8UC3
  const cv::Mat& depth() const { return depth_; }  // CV_32F, metres along the optical axis
  cv::Mat& color() { return color_; }

  // Pixel position and depth of a world point; nullopt when behind the camera.
  std::optional<Eigen::Vector3d> project(const Eigen::Vector3d& world) const;
  const Pose& camera_T_world() const { return camera_T_world_; }

private:
  struct ClipVertex {
    Eigen::Vector3d p;  // camera frame
    Eigen::Vector2f uv;
  };
  struct ScreenVertex {
    double x, y, iz;  // pixel position, 1 / depth
  };
  static ScreenVertex to_screen(const Eigen::Vector3d& p, double fx, double fy, double cx, double cy);
  // Calls paint(x, y, w0, w1, w2, 1 / depth) at each pixel centre inside the triangle where it
  // is nearer than the depth, after writing the depth there (w: barycentric weights).
  template <class Paint>
  void fill(const ScreenVertex* s, Paint&& paint);
  void draw_triangle(const ClipVertex* v, const RenderMesh& mesh, float shade);
  // The triangle's part in front of the near plane, as 3 or 4 corners to fan from the first
  // (0: all behind it).
  static int clip_near(const ClipVertex* in, ClipVertex* out);
  float shade_of(const Eigen::Vector3d& normal_camera) const;

  cv::Size size_;
  double fx_, fy_, cx_, cy_;
  Pose camera_T_world_;
  Eigen::Vector3d light_camera_;  // unit, towards the light
  cv::Mat color_, depth_;
};

}  // namespace demoplan::perception
