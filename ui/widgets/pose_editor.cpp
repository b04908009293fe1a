#include "ui/widgets/pose_editor.h"

#include <QComboBox>
#include <QFormLayout>
#include <QLabel>
#include <QSignalBlocker>
#include <QSpinBox>
#include <QVBoxLayout>

#include "ui/document/demo_poses.h"
#include "ui/widgets/pose_fields.h"
#include "ui/widgets/style.h"

namespace demoplan::ui {

PoseEditor::PoseEditor(Document* doc, QWidget* parent) : QWidget(parent), doc_(doc) {
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(6, 6, 6, 6);
  event_label_ = new QLabel(this);
  event_label_->setWordWrap(true);
  layout->addWidget(event_label_);

  auto* form = new QFormLayout;
  form->setFieldGrowthPolicy(QFormLayout::AllNonFixedFieldsGrow);
  frame_ = new QSpinBox(this);
  frame_->setKeyboardTracking(false);
  frame_->setToolTip(tr("Video frame of the selected event; change it to move the event"));
  confidence_ = new QDoubleSpinBox(this);
  confidence_->setRange(0, 100);
  confidence_->setSuffix(QStringLiteral(" %"));
  confidence_->setDecimals(0);
  confidence_->setKeyboardTracking(false);
  confidence_->setToolTip(tr("How sure the detector was; set it to 100% once you have checked the event"));
  auto* event_row = new QHBoxLayout;
  event_row->addWidget(frame_, 1);
  event_row->addWidget(new QLabel(tr("Confidence"), this));
  event_row->addWidget(confidence_, 1);
  form->addRow(tr("Frame"), event_row);
  object_ = new QComboBox(this);
  object_->setToolTip(tr("The part whose pose you edit (or click it in the 3D view)"));
  form->addRow(tr("Part"), object_);
  layout->addLayout(form);

  pose_ = new PoseFields(tr("Pose in the world"), this);
  connect(pose_, &PoseFields::edited, this, [this](const Pose& T, int field) {
    if (refreshing_ || shown_object_ < 0) return;
    if (const int c = doc_->correctionAt(shown_object_, doc_->currentFrame()); c >= 0) {
      doc_->setCorrectionPose(c, T, /*merge_key=*/field);
      return;
    }
    const int ev = doc_->editEvent();
    if (ev >= 0) doc_->setObjectPose(ev, shown_object_, T, /*merge_key=*/field);
  });
  layout->addWidget(pose_);
  note_ = new QLabel(this);
  note_->setWordWrap(true);
  QFont f = note_->font();
  f.setPointSizeF(f.pointSizeF() * 0.9);
  note_->setFont(f);
  layout->addWidget(note_);
  layout->addStretch(1);

  connect(object_, &QComboBox::currentIndexChanged, this, [this](int i) {
    if (!refreshing_) doc_->selectObject(i);
  });
  connect(frame_, &QSpinBox::valueChanged, this, [this](int f) {
    if (refreshing_) return;
    const int ev = doc_->editEvent();
    if (ev >= 0) {
      doc_->moveEvent(ev, f);
      doc_->setCurrentFrame(f);
    }
  });
  connect(confidence_, &QDoubleSpinBox::valueChanged, this, [this](double v) {
    if (!refreshing_) doc_->setEventConfidence(doc_->editEvent(), v / 100.0);
  });
  connect(doc_, &Document::projectLoaded, this, &PoseEditor::refresh);
  connect(doc_, &Document::demonstrationChanged, this, &PoseEditor::refresh);
  connect(doc_, &Document::selectionChanged, this, &PoseEditor::refresh);
  connect(doc_, &Document::currentFrameChanged, this, &PoseEditor::refresh);
  connect(doc_, &Document::correctionsChanged, this, &PoseEditor::refresh);
  refresh();
}

QDoubleSpinBox* PoseEditor::field(int i) const { return pose_->field(i); }

void PoseEditor::refresh() {
  refreshing_ = true;
  const bool has = doc_->hasProject();
  const int ev = has ? doc_->editEvent() : -1;
  int obj = has ? doc_->selectedObject() : -1;
  if (has && obj < 0 && ev >= 0) obj = doc_->demonstration().events[ev].object;
  {
    QSignalBlocker b(object_);
    object_->clear();
    if (has)
      for (const auto& id : doc_->demonstration().object_ids) object_->addItem(QString::fromStdString(id));
    object_->setCurrentIndex(obj);
  }
  if (const int c = has ? doc_->correctionAt(obj, doc_->currentFrame()) : -1; c >= 0) {
    showCorrection(c, obj);
    refreshing_ = false;
    return;
  }
  const bool editable = ev >= 0 && obj >= 0;
  pose_->setEditable(editable);
  frame_->setEnabled(ev >= 0);
  confidence_->setEnabled(ev >= 0);
  if (ev < 0) {
    event_label_->setText(has ? tr("No event: add one on the timeline (double-click a lane)") : tr("No project"));
    note_->clear();
    shown_event_ = shown_object_ = -1;
    refreshing_ = false;
    return;
  }
  const Demonstration& d = doc_->demonstration();
  const ContactEvent& e = d.events[ev];
  {
    QSignalBlocker b1(frame_), b2(confidence_);
    frame_->setRange(0, std::max(0, doc_->frameCount() - 1));
    frame_->setValue(e.frame);
    confidence_->setValue(e.confidence * 100.0);
  }
  event_label_->setText(tr("<b>%1 of %2</b> at %3%4")
                            .arg(eventTypeName(e.type), QString::fromStdString(d.object_ids[e.object]),
                                 frameText(e.frame, doc_->fps()),
                                 doc_->selectedEvent() >= 0 ? QString()
                                 : e.frame <= doc_->currentFrame() ? tr(" <i>(the last event before the playhead)</i>")
                                                                   : tr(" <i>(the first event)</i>")));
  if (obj >= 0) {
    const Pose T = world_pose_at_event(doc_->scene(), d, ev, obj, doc_->initialConfiguration());
    pose_->setPose(T, ev == shown_event_ && obj == shown_object_);
    shown_event_ = ev;
    shown_object_ = obj;
    const std::vector<size_t> rest = rest_events(d, ev, obj);
    QString note;
    if (held_at_frame(d, obj, e.frame) && !(e.object == obj))
      note = tr("%1 is held at this event.").arg(QString::fromStdString(d.object_ids[obj]));
    else if (rest.size() > 1)
      note = tr("Applies to the rest of %1 from frame %2 to %3 (%4 events): a part does not move while nobody holds it.")
                 .arg(QString::fromStdString(d.object_ids[obj]))
                 .arg(d.events[rest.front()].frame)
                 .arg(d.events[rest.back()].frame)
                 .arg(rest.size());
    if (!e.pose_frame(obj).empty())
      note += tr(" Stored relative to the robot link %1 (it rides on the robot).").arg(QString::fromStdString(e.pose_frame(obj)));
    note_->setText(note);
  }
  refreshing_ = false;
}

// A part placed again at the playhead: its pose there is the tracker's new start, not an event's.
void PoseEditor::showCorrection(int index, int object) {
  const PartCorrection& c = doc_->corrections()[static_cast<size_t>(index)];
  pose_->setEditable(true);
  frame_->setEnabled(false);
  confidence_->setEnabled(false);
  event_label_->setText(tr("<b>%1 placed again</b> at %2")
                            .arg(QString::fromStdString(c.id), frameText(c.frame, doc_->fps())));
  const int shown = -2 - index;  // apart from every event's index
  pose_->setPose(c.world_T_object, shown == shown_event_ && object == shown_object_);
  shown_event_ = shown;
  shown_object_ = object;
  note_->setText(tr("Detect Events with the part models follows %1 from this pose on: move it until its outline lies "
                    "on the part in the video. Edit > Remove This Placement takes it away.")
                     .arg(QString::fromStdString(c.id)));
}

}  // namespace demoplan::ui
