#pragma once
// The inspector: the selected event (type, frame, confidence) and the selected part's pose at
// that event, typed in millimetres and degrees (roll, pitch, yaw as URDF writes them). A change
// applies to every event of the part's rest (it cannot move while nobody holds it) and goes
// through the undo stack; consecutive steps of one field merge into one undo step. On a frame
// where the selected part was placed again (Document::corrections), that placement instead.
#include <QWidget>

#include "ui/document/document.h"

class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QSpinBox;

namespace demoplan::ui {
class PoseFields;
}

namespace demoplan::ui {

class PoseEditor : public QWidget {
  Q_OBJECT
public:
  explicit PoseEditor(Document* doc, QWidget* parent = nullptr);
  // 0..2: x, y, z in mm; 3..5: roll, pitch, yaw in degrees.
  QDoubleSpinBox* field(int i) const;
  QComboBox* objectBox() const { return object_; }
  QSpinBox* frameBox() const { return frame_; }
  QDoubleSpinBox* confidenceBox() const { return confidence_; }

private:
  void refresh();
  void showCorrection(int index, int object);

  Document* doc_;
  QLabel* event_label_;
  QComboBox* object_;
  QSpinBox* frame_;
  QDoubleSpinBox* confidence_;
  PoseFields* pose_;
  QLabel* note_;
  int shown_event_ = -1, shown_object_ = -1;
  bool refreshing_ = false;
};

}  // namespace demoplan::ui
