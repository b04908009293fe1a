// Calibrate Camera as an operator uses it: a synthetic board video (known intrinsics) is
// calibrated in the background with progress; the result shows its RMS and every view's error in
// the plot; Use This Camera writes the camera (keeping the project camera's pose) and sets it on
// the project. A missing board file is reported with its name; Cancel returns at once.
#include <QLabel>
#include <QProgressBar>
#include <QPushButton>
#include <QTemporaryDir>
#include <QtTest>

#include "perception/camera/camera_model.h"
#include "perception/synthetic/board_video.h"
#include "ui/document/document.h"
#include "ui/widgets/calibration_dialog.h"
#include "ui/widgets/calibration_error_plot.h"
#include "ui_test_support.h"

using namespace demoplan;
using namespace demoplan::ui;

class TestCalibrationDialog : public QObject {
  Q_OBJECT
  QTemporaryDir dir_;
  perception::BoardVideoOutput video_;

private slots:
  void initTestCase() {
    QVERIFY(dir_.isValid());
    perception::BoardVideoOptions o;
    o.views = 12;
    o.seed = 4;
    video_ = perception::write_board_video(o, dir_.path().toStdString());
    QVERIFY(QFileInfo::exists(QString::fromStdString(video_.video)));
  }

  void calibratesAndUsesTheCamera() {
    Document doc(test::dataDir().toStdString());
    doc.open(test::sampleProject());
    const perception::Camera* before = doc.media()->camera();
    QVERIFY(before && before->world_T_camera);
    const Pose pose = *before->world_T_camera;
    CalibrationDialog dialog(&doc);
    dialog.show();
    QVERIFY(!dialog.useButton()->isEnabled());
    dialog.setSource(QString::fromStdString(video_.video));
    dialog.setBoard(QString::fromStdString(video_.board));
    int progress_seen = 0;
    connect(dialog.progressBar(), &QProgressBar::valueChanged, this, [&](int v) { progress_seen = std::max(progress_seen, v); });
    QVERIFY(dialog.start());
    QVERIFY(dialog.isRunning());
    QVERIFY(!dialog.startButton()->isEnabled());
    QVERIFY(test::waitFor([&] { return !dialog.isRunning(); }, 60000));
    QVERIFY2(dialog.result(), qPrintable(dialog.summaryLabel()->text()));
    QVERIFY(progress_seen > 0);
    const auto& r = *dialog.result();
    QVERIFY2(r.rms_px < 0.5, qPrintable(QString::number(r.rms_px)));
    QVERIFY(std::abs(r.camera.fx - 1100) < 1100 * 0.01);
    QVERIFY(dialog.summaryLabel()->text().contains(QStringLiteral("RMS")));
    QVERIFY(dialog.useButton()->isEnabled());
    // The plot holds every candidate view; a used view is found under its bar.
    QCOMPARE(dialog.plot()->viewAt(dialog.plot()->width() / 2.0) >= 0, true);
    dialog.grab().save(test::artifactDir() + QStringLiteral("/calibration_dialog.png"));

    const QString camera_file = dir_.filePath(QStringLiteral("calibrated.json"));
    QVERIFY(dialog.useCamera(camera_file));
    QCOMPARE(doc.media()->cameraPath(), camera_file);
    QVERIFY(doc.isModified());
    const perception::Camera used = perception::load_camera(camera_file.toStdString());
    QCOMPARE(used.fx, r.camera.fx);
    QVERIFY(used.world_T_camera && used.world_T_camera->isApprox(pose));  // the camera did not move
  }

  void aMissingBoardIsNamedAndCancelReturnsAtOnce() {
    Document doc(test::dataDir().toStdString());
    CalibrationDialog dialog(&doc);
    dialog.setSource(QString::fromStdString(video_.video));
    dialog.setBoard(dir_.filePath(QStringLiteral("no_board.json")));
    QVERIFY(dialog.start());
    QVERIFY(test::waitFor([&] { return !dialog.isRunning(); }, 20000));
    QVERIFY(!dialog.result());
    QVERIFY2(dialog.summaryLabel()->text().contains(QStringLiteral("no_board.json")), qPrintable(dialog.summaryLabel()->text()));

    dialog.setBoard(QString::fromStdString(video_.board));
    QVERIFY(dialog.start());
    dialog.cancel();
    QVERIFY(!dialog.isRunning());
    QVERIFY(dialog.startButton()->isEnabled());
    QVERIFY(dialog.summaryLabel()->text().contains(QStringLiteral("Cancelled")));
    QTest::qWait(200);  // a late result of the cancelled run changes nothing
    QVERIFY(!dialog.result());
  }
};

DEMOPLAN_UI_TEST_MAIN(TestCalibrationDialog)
#include "test_calibration_dialog.moc"
