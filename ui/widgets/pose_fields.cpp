#include "ui/widgets/pose_fields.h"

#include <QDoubleSpinBox>
#include <QGridLayout>
#include <QLabel>
#include <QSignalBlocker>
#include <cmath>

#include "ui/widgets/style.h"

namespace demoplan::ui {

namespace {
constexpr double kDeg = 180.0 / M_PI;
}

PoseFields::PoseFields(const QString& title, QWidget* parent) : QGroupBox(title, parent) {
  auto* grid = new QGridLayout(this);
  const char* names[6] = {"X", "Y", "Z", QT_TR_NOOP("Roll"), QT_TR_NOOP("Pitch"), QT_TR_NOOP("Yaw")};
  const char* tips[6] = {QT_TR_NOOP("Position along the world x axis, millimetres"),
                         QT_TR_NOOP("Position along the world y axis, millimetres"),
                         QT_TR_NOOP("Height above the floor, millimetres"),
                         QT_TR_NOOP("Rotation about x, degrees (applied first)"),
                         QT_TR_NOOP("Rotation about y, degrees"),
                         QT_TR_NOOP("Rotation about z, degrees (applied last)")};
  for (int i = 0; i < 6; ++i) {
    auto* s = new QDoubleSpinBox(this);
    s->setKeyboardTracking(false);
    s->setAccelerated(true);
    if (i < 3) {
      s->setRange(-20000, 20000);
      s->setDecimals(1);
      s->setSingleStep(1.0);
      s->setSuffix(QStringLiteral(" mm"));
    } else {
      s->setRange(-360, 360);
      s->setDecimals(2);
      s->setSingleStep(1.0);
      s->setSuffix(QStringLiteral("°"));
      s->setWrapping(true);
    }
    s->setToolTip(tr(tips[i]));
    s->setAccessibleName(tr(names[i]));
    fields_[static_cast<size_t>(i)] = s;
    grid->addWidget(new QLabel(tr(names[i]), this), i % 3, (i / 3) * 2);
    grid->addWidget(s, i % 3, (i / 3) * 2 + 1);
    connect(s, &QDoubleSpinBox::valueChanged, this, [this, i] {
      if (setting_) return;
      const auto k = static_cast<size_t>(i);
      // The change the operator made to the displayed (rounded) value, applied to the exact one.
      exact_[k] += fields_[k]->value() - shown_[k];
      shown_[k] = fields_[k]->value();
      emit edited(pose_from_xyz_rpy(Eigen::Vector3d(exact_[0], exact_[1], exact_[2]) / 1000.0,
                                    Eigen::Vector3d(exact_[3], exact_[4], exact_[5]) / kDeg),
                  i);
    });
  }
  grid->setColumnStretch(1, 1);
  grid->setColumnStretch(3, 1);
}

void PoseFields::setPose(const Pose& T, bool same_target) {
  setting_ = true;
  const Eigen::Vector3d rpy = rpyFromRotation(T.linear());
  const std::array<double, 6> v = {T.translation().x() * 1000, T.translation().y() * 1000, T.translation().z() * 1000,
                                   rpy.x() * kDeg, rpy.y() * kDeg, rpy.z() * kDeg};
  // Keep the exact values while the pose is the one the fields show (rounding drift).
  for (size_t i = 0; i < 6; ++i) {
    if (!(same_target && std::abs(v[i] - exact_[i]) < (i < 3 ? 0.05 : 0.005))) exact_[i] = v[i];
    QSignalBlocker b(fields_[i]);
    fields_[i]->setValue(exact_[i]);
    shown_[i] = fields_[i]->value();
  }
  setting_ = false;
}

void PoseFields::setEditable(bool on) {
  for (auto* f : fields_) f->setEnabled(on);
}

}  // namespace demoplan::ui
