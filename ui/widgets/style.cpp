#include "ui/widgets/style.h"

#include <QPainter>
#include <QPainterPath>
#include <cmath>

namespace demoplan::ui {

QColor objectColor(int object) {
  static const QColor palette[] = {QColor(0x1f, 0x77, 0xb4), QColor(0x94, 0x67, 0xbd), QColor(0x17, 0xbe, 0xcf),
                                   QColor(0xe3, 0x77, 0xc2), QColor(0x8c, 0x56, 0x4b), QColor(0xbc, 0xbd, 0x22),
                                   QColor(0x7f, 0x7f, 0x7f), QColor(0x2c, 0xa0, 0x2c)};
  if (object < 0) return QColor(0x7f, 0x7f, 0x7f);
  return palette[object % 8];
}

QColor eventColor(EventType type) {
  return type == EventType::Grasp ? QColor(0x2e, 0x9d, 0x4a) : QColor(0xe0, 0x5a, 0x1b);
}

QColor treeColor(int tree) {
  // Golden-angle hues: neighbouring tree indices get clearly different colours.
  const double hue = std::fmod(0.58 + 0.618033988749895 * std::max(0, tree), 1.0);
  return QColor::fromHsvF(float(hue), 0.75f, 0.95f);
}

void paintPlacementMark(QPainter& p, const QRectF& box, int object, const QColor& outline) {
  QPainterPath diamond;
  diamond.moveTo(box.center().x(), box.top());
  diamond.lineTo(box.right(), box.center().y());
  diamond.lineTo(box.center().x(), box.bottom());
  diamond.lineTo(box.left(), box.center().y());
  diamond.closeSubpath();
  p.setPen(QPen(outline, 1.2));
  p.setBrush(objectColor(object));
  p.drawPath(diamond);
}

QString eventTypeName(EventType type) { return type == EventType::Grasp ? QStringLiteral("grasp") : QStringLiteral("release"); }

QString frameText(int frame, double fps) {
  return QStringLiteral("frame %1 (%2 s)").arg(frame).arg(fps > 0 ? frame / fps : 0.0, 0, 'f', 2);
}

Eigen::Vector3d rpyFromRotation(const Eigen::Matrix3d& R) {
  const double pitch = std::asin(std::clamp(-R(2, 0), -1.0, 1.0));
  double roll, yaw;
  if (std::abs(R(2, 0)) < 1.0 - 1e-9) {
    roll = std::atan2(R(2, 1), R(2, 2));
    yaw = std::atan2(R(1, 0), R(0, 0));
  } else {  // gimbal lock: put everything in yaw
    roll = 0.0;
    yaw = std::atan2(-R(0, 1), R(1, 1));
  }
  return {roll, pitch, yaw};
}

}  // namespace demoplan::ui
