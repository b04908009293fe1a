#pragma once
// Six fields for a pose in the world: x, y, z in millimetres and roll, pitch, yaw in degrees (as
// URDF writes them). The fields keep the exact pose behind their rounded text, so editing one
// field does not nudge the others; each edit reports the whole pose and which field changed.
#include <QGroupBox>
#include <array>

#include "core/geometry/se3.h"

class QDoubleSpinBox;

namespace demoplan::ui {

class PoseFields : public QGroupBox {
  Q_OBJECT
public:
  explicit PoseFields(const QString& title, QWidget* parent = nullptr);
  // 0..2: x, y, z in mm; 3..5: roll, pitch, yaw in degrees.
  QDoubleSpinBox* field(int i) const { return fields_[static_cast<size_t>(i)]; }
  // Shows `pose`; `same_target` says it is the pose of what was shown before (then a value the
  // fields show up to rounding keeps its exact value).
  void setPose(const Pose& pose, bool same_target);
  void setEditable(bool on);

signals:
  void edited(const Pose& pose, int field);

private:
  std::array<QDoubleSpinBox*, 6> fields_{};
  std::array<double, 6> exact_{};
  std::array<double, 6> shown_{};  // what the fields displayed when last set
  bool setting_ = false;
};

}  // namespace demoplan::ui
