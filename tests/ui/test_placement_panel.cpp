// Where to put the robot, in the GUI (issue 18): the search runs in the background and the heat
// map fills in as candidates arrive; a click chooses a candidate and "Stand the Robot Here and
// Plan" moves the robot (one undo step, saved with the project) and plans a valid path there;
// Cancel answers at once; an inverted region is refused with a message.
#include <QDoubleSpinBox>
#include <QLabel>
#include <QProgressBar>
#include <QPushButton>
#include <QSpinBox>
#include <QTemporaryDir>
#include <QtTest>

#include "ui/document/document.h"
#include "ui/widgets/placement_map_view.h"
#include "ui/widgets/placement_panel.h"
#include "ui_test_support.h"

using namespace demoplan;
using namespace demoplan::ui;

class TestPlacementPanel : public QObject {
  Q_OBJECT
private slots:
  void searchFillsTheMapAndTheRobotStandsWhereChosen() {
    Document doc(test::dataDir().toStdString());
    doc.open(test::sampleProject());  // shelf_1, Panda at pose 0
    const Pose published = doc.scene().robot.base;
    PlacementSearchSettings s = doc.placement()->settings();
    // The default region: 1.2 m around the robot, every yaw.
    QCOMPARE(s.region.x.low, published.translation().x() - 0.6);
    QCOMPARE(s.region.yaw.high, M_PI);
    s.region.x = {0.1, 0.5};
    s.region.y = {0.0, 0.4};
    s.samples = 6;
    s.seeds = 1;
    s.time_limit_s = 20;
    doc.placement()->setSettings(s);
    PlacementPanel panel(&doc);
    panel.resize(1100, 380);
    panel.show();
    QCOMPARE(panel.samplesBox()->value(), 6);

    int arrivals = 0;
    connect(doc.placement(), &PlacementSearchJob::candidateDone, this, [&] { ++arrivals; });
    QTest::mouseClick(panel.searchButton(), Qt::LeftButton);
    QVERIFY(doc.placement()->isRunning());
    QVERIFY(!panel.searchButton()->isEnabled());
    QVERIFY(panel.cancelButton()->isEnabled());
    QVERIFY(test::waitFor([&] { return !doc.placement()->isRunning(); }, 120000));
    QCOMPARE(arrivals, 6);  // one by one, as they were done
    QCOMPARE(panel.progressBar()->value(), 6);
    QCOMPARE(static_cast<int>(doc.placement()->candidates().size()), 6);
    const PlacementCandidate* best = doc.placement()->best();
    QVERIFY(best != nullptr);
    QVERIFY(best->cycle_time_s().value() > 2.0);
    // The best is chosen on the map; its numbers are shown.
    const int chosen = panel.mapView()->chosen();
    QVERIFY(chosen >= 0);
    QCOMPARE(doc.placement()->candidates()[static_cast<size_t>(chosen)].index, best->index);
    QVERIFY(panel.mapView()->describe(chosen).contains(QStringLiteral("cycle time")));
    QVERIFY(panel.standButton()->isEnabled());
    QImage picture = panel.grab().toImage();
    picture.save(test::artifactDir() + QStringLiteral("/placement_panel.png"));

    // A click on a grey square (a candidate without a plan) tells why, and cannot be stood on.
    for (size_t i = 0; i < doc.placement()->candidates().size(); ++i)
      if (!doc.placement()->candidates()[i].feasible) {
        panel.mapView()->choose(static_cast<int>(i));
        QVERIFY(!panel.standButton()->isEnabled());
        QVERIFY(!panel.mapView()->describe(static_cast<int>(i)).isEmpty());
        break;
      }
    panel.mapView()->choose(chosen);

    // A double click on the best square stands the robot there: it moves, the planner runs and
    // finds a valid path from there.
    std::vector<QPoint> hits;  // pixels of its square, found through the view's own hit test
    for (int y = 0; y < panel.mapView()->height(); y += 2)
      for (int x = 0; x < panel.mapView()->width(); x += 2)
        if (panel.mapView()->candidateAt(QPointF(x, y)) == chosen) hits.emplace_back(x, y);
    QVERIFY(!hits.empty());
    const QPoint square = hits[hits.size() / 2];
    QVERIFY(panel.mapView()->candidateAt(square) == chosen);
    QTest::mouseDClick(panel.mapView(), Qt::LeftButton, Qt::NoModifier, square);
    QVERIFY((doc.scene().robot.base.translation() - best->base.pose().translation()).norm() < 1e-12);
    QVERIFY(doc.sceneReference().base.has_value());
    QVERIFY(test::waitFor([&] { return !doc.planning()->isRunning() && doc.planning()->result(); }, 120000));
    QVERIFY2(doc.planning()->result()->summary.valid, doc.planning()->result()->summary.message.c_str());
    QVERIFY(!doc.planning()->resultStale());

    // Saved with the project and read back; one undo puts the robot back on its published pose.
    QTemporaryDir dir;
    const QString file = dir.filePath(QStringLiteral("moved.demoplan"));
    doc.saveAs(file);
    Document reopened(test::dataDir().toStdString());
    reopened.open(file);
    QVERIFY(reopened.sceneReference().base == doc.sceneReference().base);
    QVERIFY((reopened.scene().robot.base.matrix() - doc.scene().robot.base.matrix()).norm() < 1e-9);
    doc.undoStack()->undo();
    QVERIFY((doc.scene().robot.base.matrix() - published.matrix()).norm() < 1e-12);
    QVERIFY(!doc.sceneReference().base.has_value());
    QVERIFY(doc.planning()->resultStale());  // planned for the other base
  }

  void aCellsRobotIsStoodElsewhereWithItsPedestal() {
    Document doc(test::dataDir().toStdString());
    doc.newFromCell(test::dataDir().toStdString() + "/../cells/ur5_workbench.json");
    QTemporaryDir dir;
    const std::string mine = dir.filePath(QStringLiteral("workbench.json")).toStdString();
    doc.saveCellAs(QString::fromStdString(mine));  // a bundled cell is not edited in place
    const Pose pedestal = doc.cell()->furniture[0].pose, robot = doc.cell()->robot.base;
    doc.setRobotBase({-0.1, 0.2, 0.75, 0.7});
    QVERIFY((doc.cell()->robot.base.translation() - Eigen::Vector3d(-0.1, 0.2, 0.75)).norm() < 1e-12);
    QVERIFY((doc.cell()->furniture[0].pose.translation() - Eigen::Vector3d(-0.1, 0.2, 0.375)).norm() < 1e-12);
    QVERIFY(doc.cell()->furniture[1].pose.isApprox(load_cell(test::dataDir().toStdString() + "/../cells/ur5_workbench.json").furniture[1].pose));
    const Cell written = load_cell(mine);  // written to the cell file at once
    QVERIFY((written.furniture[0].pose.translation() - Eigen::Vector3d(-0.1, 0.2, 0.375)).norm() < 1e-9);
    doc.undoStack()->undo();
    QVERIFY(doc.cell()->furniture[0].pose.isApprox(pedestal));
    QVERIFY(doc.cell()->robot.base.isApprox(robot));
  }

  void cancelAnswersAtOnceAndAnInvertedRegionIsRefused() {
    Document doc(test::dataDir().toStdString());
    doc.open(test::sampleProject());
    PlacementPanel panel(&doc);
    panel.show();
    panel.samplesBox()->setValue(200);
    QTest::mouseClick(panel.searchButton(), Qt::LeftButton);
    QVERIFY(doc.placement()->isRunning());
    QElapsedTimer t;
    t.start();
    QTest::mouseClick(panel.cancelButton(), Qt::LeftButton);
    QVERIFY(!doc.placement()->isRunning());
    QVERIFY(t.elapsed() < 100);
    QVERIFY(panel.searchButton()->isEnabled());
    QVERIFY(doc.placement()->candidates().size() < 200u);

    auto* x0 = panel.findChildren<QDoubleSpinBox*>().front();  // x from
    x0->setValue(5.0);
    QTest::mouseClick(panel.searchButton(), Qt::LeftButton);
    QVERIFY(!doc.placement()->isRunning());
    QVERIFY(panel.messageLabel()->text().contains(QStringLiteral("inverted")));
  }
};

DEMOPLAN_UI_TEST_MAIN(TestPlacementPanel)
#include "test_placement_panel.moc"
