#include "perception/render/rasterizer.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace demoplan::perception {

namespace {
constexpr double kNear = 0.05;  // m
}

Rasterizer::Rasterizer(cv::Size size, double fx, double fy, double cx, double cy, const Pose& world_T_camera)
    : size_(size), fx_(fx), fy_(fy), cx_(cx), cy_(cy), camera_T_world_(world_T_camera.inverse()) {
  // Light from above, a little from the camera's side.
  const Eigen::Vector3d light_world = Eigen::Vector3d(0.25, -0.35, 1.0).normalized();
  const Eigen::Vector3d towards_camera = -world_T_camera.linear().col(2);
  light_camera_ = (camera_T_world_.linear() * (light_world + 0.3 * towards_camera).normalized()).normalized();
  color_.create(size, CV_8UC3);
  depth_.create(size, CV_32F);
}

void Rasterizer::clear(const cv::Vec3b& top, const cv::Vec3b& bottom) {
  for (int y = 0; y < size_.height; ++y) {
    const double a = static_cast<double>(y) / std::max(1, size_.height - 1);
    cv::Vec3b c;
    for (int k = 0; k < 3; ++k) c[k] = cv::saturate_cast<uchar>(top[k] * (1 - a) + bottom[k] * a);
    color_.row(y).setTo(c);
  }
  depth_.setTo(std::numeric_limits<float>::infinity());
}

void Rasterizer::restore(const cv::Mat& color, const cv::Mat& depth) {
  if (!color.empty()) color.copyTo(color_);
  depth.copyTo(depth_);
}

std::optional<Eigen::Vector3d> Rasterizer::project(const Eigen::Vector3d& world) const {
  const Eigen::Vector3d p = camera_T_world_ * world;
  if (p.z() < kNear) return std::nullopt;
  return Eigen::Vector3d(fx_ * p.x() / p.z() + cx_, fy_ * p.y() / p.z() + cy_, p.z());
}

float Rasterizer::shade_of(const Eigen::Vector3d& n) const {
  return static_cast<float>(0.45 + 0.55 * std::max(0.0, n.dot(light_camera_)));
}

int Rasterizer::clip_near(const ClipVertex* in, ClipVertex* out) {
  int behind = 0;
  for (int k = 0; k < 3; ++k) behind += in[k].p.z() < kNear;
  if (behind == 3) return 0;
  if (behind == 0) {
    std::copy(in, in + 3, out);
    return 3;
  }
  // Sutherland-Hodgman against the near plane.
  int m = 0;
  for (int k = 0; k < 3; ++k) {
    const ClipVertex& a = in[k];
    const ClipVertex& b = in[(k + 1) % 3];
    const bool ain = a.p.z() >= kNear, bin = b.p.z() >= kNear;
    if (ain) out[m++] = a;
    if (ain != bin) {
      const double s = (kNear - a.p.z()) / (b.p.z() - a.p.z());
      out[m].p = a.p + s * (b.p - a.p);
      out[m].uv = a.uv + static_cast<float>(s) * (b.uv - a.uv);
      ++m;
    }
  }
  return m;
}

void Rasterizer::draw(const RenderMesh& mesh, const Pose& world_T_mesh) {
  const Pose T = camera_T_world_ * world_T_mesh;
  const Eigen::Matrix3d R = T.linear();
  const Eigen::Vector3d t = T.translation();
  std::vector<Eigen::Vector3d> cam(mesh.vertices.size());
  for (size_t i = 0; i < cam.size(); ++i) cam[i] = R * mesh.vertices[i].cast<double>() + t;
  const bool textured = !mesh.texture.empty() && !mesh.uvs.empty();
  for (const auto& tri : mesh.triangles) {
    ClipVertex in[3];
    for (int k = 0; k < 3; ++k) {
      in[k].p = cam[tri[k]];
      in[k].uv = textured ? mesh.uvs[tri[k]] : Eigen::Vector2f::Zero();
    }
    if (in[0].p.z() < kNear && in[1].p.z() < kNear && in[2].p.z() < kNear) continue;
    Eigen::Vector3d n = (in[1].p - in[0].p).cross(in[2].p - in[0].p);
    const double len = n.norm();
    if (len < 1e-15) continue;
    n /= len;
    if (n.dot(in[0].p) > 0) n = -n;  // two-sided: the side facing the camera
    const float shade = shade_of(n);
    ClipVertex out[4];
    const int m = clip_near(in, out);
    for (int k = 1; k + 1 < m; ++k) {
      const ClipVertex fan[3] = {out[0], out[k], out[k + 1]};
      draw_triangle(fan, mesh, shade);
    }
  }
}

void Rasterizer::draw_depth(const RenderMesh& mesh, const Pose& world_T_mesh, cv::Mat* labels, uchar label) {
  const Pose T = camera_T_world_ * world_T_mesh;
  const Eigen::Matrix3d R = T.linear();
  const Eigen::Vector3d t = T.translation();
  std::vector<Eigen::Vector3d> cam(mesh.vertices.size());
  std::vector<ScreenVertex> screen(mesh.vertices.size());
  for (size_t i = 0; i < cam.size(); ++i) {
    cam[i] = R * mesh.vertices[i].cast<double>() + t;
    if (cam[i].z() >= kNear) screen[i] = to_screen(cam[i], fx_, fy_, cx_, cy_);
  }
  auto paint = [&](int x, int y, double, double, double, double) {
    if (labels) labels->ptr<uchar>(y)[x] = label;
  };
  for (const auto& tri : mesh.triangles) {
    const Eigen::Vector3d &a = cam[tri[0]], &b = cam[tri[1]], &c = cam[tri[2]];
    const int behind = (a.z() < kNear) + (b.z() < kNear) + (c.z() < kNear);
    if (behind == 3 || (b - a).cross(c - a).norm() < 1e-15) continue;  // as draw skips them
    if (behind == 0) {
      const ScreenVertex v[3] = {screen[tri[0]], screen[tri[1]], screen[tri[2]]};
      fill(v, paint);
      continue;
    }
    const ClipVertex in[3] = {{a, Eigen::Vector2f::Zero()}, {b, Eigen::Vector2f::Zero()}, {c, Eigen::Vector2f::Zero()}};
    ClipVertex out[4];
    const int m = clip_near(in, out);
    for (int k = 1; k + 1 < m; ++k) {
      const ScreenVertex v[3] = {to_screen(out[0].p, fx_, fy_, cx_, cy_), to_screen(out[k].p, fx_, fy_, cx_, cy_),
                                 to_screen(out[k + 1].p, fx_, fy_, cx_, cy_)};
      fill(v, paint);
    }
  }
}

Rasterizer::ScreenVertex Rasterizer::to_screen(const Eigen::Vector3d& p, double fx, double fy, double cx, double cy) {
  const double iz = 1.0 / p.z();
  return {fx * p.x() * iz + cx, fy * p.y() * iz + cy, iz};
}

template <class Paint>
void Rasterizer::fill(const ScreenVertex* s, Paint&& paint) {
  const double area = (s[1].x - s[0].x) * (s[2].y - s[0].y) - (s[1].y - s[0].y) * (s[2].x - s[0].x);
  if (std::abs(area) < 1e-12) return;
  const int x0 = std::max(0, static_cast<int>(std::ceil(std::min({s[0].x, s[1].x, s[2].x}))));
  const int x1 = std::min(size_.width - 1, static_cast<int>(std::floor(std::max({s[0].x, s[1].x, s[2].x}))));
  const int y0 = std::max(0, static_cast<int>(std::ceil(std::min({s[0].y, s[1].y, s[2].y}))));
  const int y1 = std::min(size_.height - 1, static_cast<int>(std::floor(std::max({s[0].y, s[1].y, s[2].y}))));
  if (x0 > x1 || y0 > y1) return;
  const double inv = 1.0 / area;
  // Barycentric weights as affine functions of the pixel position.
  const double a0x = (s[1].y - s[2].y) * inv, a0y = (s[2].x - s[1].x) * inv;
  const double a1x = (s[2].y - s[0].y) * inv, a1y = (s[0].x - s[2].x) * inv;
  const double c0 = ((s[1].x - x0) * (s[2].y - y0) - (s[1].y - y0) * (s[2].x - x0)) * inv;
  const double c1 = ((s[2].x - x0) * (s[0].y - y0) - (s[2].y - y0) * (s[0].x - x0)) * inv;
  constexpr double eps = -1e-9;
  for (int y = y0; y <= y1; ++y) {
    double w0 = c0 + a0y * (y - y0), w1 = c1 + a1y * (y - y0);
    auto* drow = depth_.ptr<float>(y);
    for (int x = x0; x <= x1; ++x, w0 += a0x, w1 += a1x) {
      const double w2 = 1.0 - w0 - w1;
      if (w0 < eps || w1 < eps || w2 < eps) continue;
      const double izp = w0 * s[0].iz + w1 * s[1].iz + w2 * s[2].iz;
      const float z = static_cast<float>(1.0 / izp);
      if (z >= drow[x]) continue;
      drow[x] = z;
      paint(x, y, w0, w1, w2, izp);
    }
  }
}

void Rasterizer::draw_triangle(const ClipVertex* v, const RenderMesh& mesh, float shade) {
  ScreenVertex s[3];
  float uz[3], vz[3];
  for (int k = 0; k < 3; ++k) {
    s[k] = to_screen(v[k].p, fx_, fy_, cx_, cy_);
    uz[k] = static_cast<float>(v[k].uv.x() * s[k].iz);
    vz[k] = static_cast<float>(v[k].uv.y() * s[k].iz);
  }
  const bool textured = !mesh.texture.empty() && !mesh.uvs.empty();
  const int tw = mesh.texture.cols, th = mesh.texture.rows;
  const float cb = mesh.color[0] * shade, cg = mesh.color[1] * shade, cr = mesh.color[2] * shade;
  fill(s, [&](int x, int y, double w0, double w1, double w2, double izp) {
    cv::Vec3b& pixel = color_.ptr<cv::Vec3b>(y)[x];
    if (!textured) {
      pixel = cv::Vec3b(cv::saturate_cast<uchar>(cb), cv::saturate_cast<uchar>(cg), cv::saturate_cast<uchar>(cr));
      return;
    }
    const double u = (w0 * uz[0] + w1 * uz[1] + w2 * uz[2]) / izp;
    const double vv = (w0 * vz[0] + w1 * vz[1] + w2 * vz[2]) / izp;
    const int tx = std::clamp(static_cast<int>(u * (tw - 1) + 0.5), 0, tw - 1);
    const int ty = std::clamp(static_cast<int>((1.0 - vv) * (th - 1) + 0.5), 0, th - 1);
    const cv::Vec3b t = mesh.texture.at<cv::Vec3b>(ty, tx);
    pixel = cv::Vec3b(cv::saturate_cast<uchar>(t[0] * shade), cv::saturate_cast<uchar>(t[1] * shade),
                      cv::saturate_cast<uchar>(t[2] * shade));
  });
}

void Rasterizer::draw_marker(const cv::Mat& image, double side, const Pose& world_T_marker) {
  const Pose T = camera_T_world_ * world_T_marker;
  const Eigen::Matrix3d R = T.linear();
  const Eigen::Vector3d o = T.translation(), n = R.col(2), ex = R.col(0), ey = R.col(1);
  if (n.dot(o) >= 0) return;  // seen from behind or edge-on
  const double h = side / 2;
  double xmin = 1e18, xmax = -1e18, ymin = 1e18, ymax = -1e18;
  for (int k = 0; k < 4; ++k) {
    const Eigen::Vector3d c = o + ex * (k & 1 ? h : -h) + ey * (k & 2 ? h : -h);
    if (c.z() < kNear) return;
    const double px = fx_ * c.x() / c.z() + cx_, py = fy_ * c.y() / c.z() + cy_;
    xmin = std::min(xmin, px), xmax = std::max(xmax, px), ymin = std::min(ymin, py), ymax = std::max(ymax, py);
  }
  const int x0 = std::max(0, static_cast<int>(std::floor(xmin))), x1 = std::min(size_.width - 1, static_cast<int>(std::ceil(xmax)));
  const int y0 = std::max(0, static_cast<int>(std::floor(ymin))), y1 = std::min(size_.height - 1, static_cast<int>(std::ceil(ymax)));
  const float shade = shade_of(n);
  const double plane = n.dot(o);
  const int W = image.cols, H = image.rows;
  constexpr int kSub = 4;
  for (int y = y0; y <= y1; ++y) {
    auto* crow = color_.ptr<cv::Vec3b>(y);
    auto* drow = depth_.ptr<float>(y);
    for (int x = x0; x <= x1; ++x) {
      int covered = 0;
      double sum = 0.0, zmin = 1e18;
      for (int sy = 0; sy < kSub; ++sy)
        for (int sx = 0; sx < kSub; ++sx) {
          const double u = x + (sx + 0.5) / kSub - 0.5, v = y + (sy + 0.5) / kSub - 0.5;
          const Eigen::Vector3d d((u - cx_) / fx_, (v - cy_) / fy_, 1.0);
          const double t = plane / n.dot(d);
          if (t <= 0) continue;
          const Eigen::Vector3d q = t * d - o;
          const double mx = q.dot(ex), my = q.dot(ey);
          if (std::abs(mx) > h || std::abs(my) > h) continue;
          if (t >= drow[x]) continue;  // hidden at this sample
          const int col = std::min(W - 1, static_cast<int>((mx + h) / side * W));
          const int row = std::min(H - 1, static_cast<int>((h - my) / side * H));
          sum += image.at<uchar>(row, col);
          ++covered;
          zmin = std::min(zmin, t);
        }
      if (!covered) continue;
      const double a = static_cast<double>(covered) / (kSub * kSub);
      const double value = sum / covered * shade;
      cv::Vec3b& c = crow[x];
      for (int k = 0; k < 3; ++k) c[k] = cv::saturate_cast<uchar>((1 - a) * c[k] + a * value);
      if (a >= 0.5) drow[x] = static_cast<float>(zmin);
    }
  }
}

}  // namespace demoplan::perception
