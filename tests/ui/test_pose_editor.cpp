// The pose editor changes the selected part's pose (millimetres, degrees) at the selected event
// and at every event of the same rest; undo restores it.
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QUndoStack>
#include <QtTest>

#include "ui/document/demo_poses.h"
#include "ui/document/document.h"
#include "ui/widgets/pose_editor.h"
#include "ui/widgets/style.h"
#include "ui_test_support.h"

using namespace demoplan;
using namespace demoplan::ui;

class TestPoseEditor : public QObject {
  Q_OBJECT
  std::unique_ptr<Document> doc_;
  std::unique_ptr<PoseEditor> editor_;

  Pose poseAt(int event, int object) const {
    return world_pose_at_event(doc_->scene(), doc_->demonstration(), size_t(event), object, doc_->initialConfiguration());
  }

private slots:
  void init() {
    doc_ = std::make_unique<Document>(test::dataDir().toStdString());
    doc_->open(test::sampleProject());
    editor_ = std::make_unique<PoseEditor>(doc_.get());
    editor_->show();
  }
  void cleanup() {
    editor_.reset();
    doc_.reset();
  }

  void showsMillimetresAndDegrees() {
    doc_->selectEvent(1);  // release of YCBV_05 at 48
    QCOMPARE(editor_->objectBox()->currentIndex(), 1);
    const Pose T = poseAt(1, 1);
    QCOMPARE(editor_->field(0)->value(), std::round(T.translation().x() * 10000) / 10);
    QCOMPARE(editor_->field(2)->value(), std::round(T.translation().z() * 10000) / 10);
    const Eigen::Vector3d rpy = rpyFromRotation(T.linear()) * 180 / M_PI;
    QVERIFY(std::abs(editor_->field(5)->value() - rpy.z()) < 0.006);
    QCOMPARE(editor_->frameBox()->value(), 48);
  }

  void editingMovesThePartForItsWholeRest() {
    doc_->selectEvent(1);
    const Pose before = poseAt(1, 1);
    const Json original = demonstration_to_json(doc_->demonstration());
    QDoubleSpinBox* x = editor_->field(0);
    x->setValue(x->value() + 25.0);  // +25 mm
    const Pose after = poseAt(1, 1);
    QVERIFY(std::abs((after.translation() - before.translation()).x() - 0.025) < 1e-4);
    QVERIFY(std::abs((after.translation() - before.translation()).y()) < 1e-9);
    QVERIFY((after.linear() - before.linear()).norm() < 1e-6);  // the rotation did not drift
    // The part rests there until it is grasped again: events 2 and 3 agree.
    for (int e : {2, 3}) QVERIFY((poseAt(e, 1).translation() - after.translation()).norm() < 1e-9);
    // ...but not before it was put down (event 0: still at the grasp pose).
    QVERIFY((poseAt(0, 1).translation() - before.translation()).norm() > 0.1);

    QDoubleSpinBox* yaw = editor_->field(5);
    yaw->setValue(yaw->value() + 10.0);
    const Eigen::Matrix3d turn = poseAt(1, 1).linear() * after.linear().transpose();
    QVERIFY(std::abs(Eigen::AngleAxisd(turn).angle() - 10 * M_PI / 180) < 1e-6);
    QVERIFY(std::abs(Eigen::AngleAxisd(turn).axis().z()) > 0.999);  // about the vertical

    QCOMPARE(doc_->undoStack()->count(), 2);  // one step per field
    doc_->undoStack()->undo();
    doc_->undoStack()->undo();
    QCOMPARE(demonstration_to_json(doc_->demonstration()), original);
    QCOMPARE(x->value(), std::round(before.translation().x() * 10000) / 10);  // the fields follow
  }

  void repeatedStepsOfOneFieldAreOneUndoStep() {
    doc_->selectEvent(3);  // release of YCBV_02
    QDoubleSpinBox* z = editor_->field(2);
    const double z0 = z->value();
    for (int i = 0; i < 5; ++i) z->stepBy(1);
    QCOMPARE(z->value(), z0 + 5.0);
    QCOMPARE(doc_->undoStack()->count(), 1);
    doc_->undoStack()->undo();
    QCOMPARE(z->value(), z0);
  }

  void changingTheFrameMovesTheEvent() {
    doc_->selectEvent(3);
    editor_->frameBox()->setValue(110);
    QCOMPARE(doc_->demonstration().events[3].frame, 110);
    QCOMPARE(doc_->currentFrame(), 110);
    doc_->undoStack()->undo();
    QCOMPARE(doc_->demonstration().events[3].frame, 97);
  }
};

DEMOPLAN_UI_TEST_MAIN(TestPoseEditor)
#include "test_pose_editor.moc"
