#include "ui/view3d/orbit_camera.h"

#include <QPointF>
#include <QSize>
#include <algorithm>
#include <cmath>

namespace demoplan::ui {

namespace {
constexpr float kRad = float(M_PI / 180.0);
}

QVector3D OrbitCamera::eye() const {
  const float cp = std::cos(pitch_deg * kRad), sp = std::sin(pitch_deg * kRad);
  const float cy = std::cos(yaw_deg * kRad), sy = std::sin(yaw_deg * kRad);
  return target + distance * QVector3D(cp * cy, cp * sy, sp);
}

QMatrix4x4 OrbitCamera::view() const {
  QMatrix4x4 v;
  v.lookAt(eye(), target, QVector3D(0, 0, 1));
  return v;
}

QMatrix4x4 OrbitCamera::projection(float aspect) const {
  QMatrix4x4 p;
  const float near_plane = std::max(0.005f, distance * 0.01f);
  p.perspective(fov_deg, aspect, near_plane, distance * 20.0f + 20.0f);
  return p;
}

QVector3D OrbitCamera::right() const {
  const float cy = std::cos(yaw_deg * kRad), sy = std::sin(yaw_deg * kRad);
  return QVector3D(-sy, cy, 0);
}

QVector3D OrbitCamera::up() const {
  const QVector3D forward = (target - eye()).normalized();
  return QVector3D::crossProduct(right(), forward).normalized();
}

void OrbitCamera::orbit(float dx, float dy) {
  yaw_deg = std::fmod(yaw_deg - dx * 0.35f, 360.0f);
  pitch_deg = std::clamp(pitch_deg + dy * 0.35f, -89.0f, 89.0f);
}

void OrbitCamera::pan(float dx, float dy, float viewport_height) {
  const float world_per_px = 2.0f * distance * std::tan(fov_deg * kRad / 2) / std::max(1.0f, viewport_height);
  target += (-dx * right() + dy * up()) * world_per_px;
}

void OrbitCamera::zoom(float steps) { distance = std::clamp(distance * std::pow(0.88f, steps), 0.05f, 200.0f); }

void OrbitCamera::fit(const QVector3D& center, float radius, float aspect) {
  target = center;
  const float half_v = fov_deg * kRad / 2;
  const float half_h = std::atan(std::tan(half_v) * aspect);
  distance = std::max(0.1f, radius / std::sin(std::min(half_v, half_h)) * 1.02f);
}

Ray OrbitCamera::rayAt(const QPointF& pixel, const QSize& size) const {
  const float aspect = float(size.width()) / std::max(1, size.height());
  const QMatrix4x4 inv = (projection(aspect) * view()).inverted();
  const float x = float(2.0 * pixel.x() / size.width() - 1.0);
  const float y = float(1.0 - 2.0 * pixel.y() / size.height());
  const QVector3D a = inv.map(QVector3D(x, y, -1.0f));
  const QVector3D b = inv.map(QVector3D(x, y, 1.0f));
  return {a, (b - a).normalized()};
}

bool OrbitCamera::project(const QVector3D& world, const QSize& size, QPointF& pixel) const {
  const float aspect = float(size.width()) / std::max(1, size.height());
  const QVector4D clip = projection(aspect) * view() * QVector4D(world, 1.0f);
  if (clip.w() <= 1e-6f) return false;
  const float x = clip.x() / clip.w(), y = clip.y() / clip.w();
  pixel = QPointF((x + 1.0) * 0.5 * size.width(), (1.0 - y) * 0.5 * size.height());
  return true;
}

}  // namespace demoplan::ui
