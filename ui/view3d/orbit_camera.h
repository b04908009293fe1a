#pragma once
// An orbit camera around a target point, z up (the robot world's convention): yaw about z,
// pitch above the horizon, distance; perspective projection. Plain math, testable without GL.
#include <QMatrix4x4>
#include <QVector3D>

namespace demoplan::ui {

struct Ray {
  QVector3D origin, direction;  // direction normalised
};

class OrbitCamera {
public:
  QVector3D target{0.3f, 0.0f, 0.6f};
  float yaw_deg = 35.0f;    // 0: looking along -x from +x
  float pitch_deg = 28.0f;  // above the horizon
  float distance = 3.0f;
  float fov_deg = 40.0f;

  QVector3D eye() const;
  QMatrix4x4 view() const;
  QMatrix4x4 projection(float aspect) const;
  // Camera right and up in the world.
  QVector3D right() const;
  QVector3D up() const;

  void orbit(float dx_px, float dy_px);
  void pan(float dx_px, float dy_px, float viewport_height_px);
  void zoom(float steps);  // > 0 moves closer
  // Frames a sphere so it fills a view of this aspect ratio (width / height).
  void fit(const QVector3D& center, float radius, float aspect = 1.0f);
  // The ray through a pixel of a viewport of `size`.
  Ray rayAt(const QPointF& pixel, const QSize& size) const;
  // Pixel of a world point (y down); false when behind the camera.
  bool project(const QVector3D& world, const QSize& size, QPointF& pixel) const;
};

}  // namespace demoplan::ui
