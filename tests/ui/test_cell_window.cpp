// Markers stuck on a part by clicking it in the real main window's 3D view (OpenGL: run under
// xvfb-run): a new cell with a block on its table, Stick Markers on, a click on the block; the
// marker lands on the face that was clicked, facing the camera, and is listed and drawn. The
// table is clicked and moved with the gizmo.
// Screenshot in build/test-artifacts/ui/.
#include <QDir>
#include <QListWidget>
#include <QTemporaryDir>
#include <QtTest>

#include "core/cell/cell_edits.h"
#include "tests/support/box_stl.h"
#include "ui/mainwindow/main_window.h"
#include "ui/view3d/scene_view.h"
#include "ui/widgets/cell_panel.h"
#include "ui_test_support.h"

using namespace demoplan;
using namespace demoplan::ui;

class TestCellWindow : public QObject {
  Q_OBJECT
  QTemporaryDir dir_;
  std::unique_ptr<MainWindow> window_;

private slots:
  void initTestCase() {
    if (ui::test::glUnavailable()) QSKIP("needs an X server for QOpenGLWidget: run under xvfb-run (test.sh does)");
    QVERIFY(dir_.isValid());
    MainWindowOptions o;
    o.data_dir = ui::test::dataDir().toStdString();
    o.interactive = false;
    o.restore_layout = false;
    window_ = std::make_unique<MainWindow>(o);
    window_->resize(1280, 800);
    window_->show();
    QVERIFY(QTest::qWaitForWindowExposed(window_.get()));
  }
  void cleanupTestCase() { window_.reset(); }

  void aClickOnAPartSticksAMarkerOnTheFaceUnderIt() {
    const std::string cell = dir_.filePath(QStringLiteral("cell.json")).toStdString();
    save_cell(cell, starter_cell(cell, "ur5", ui::test::dataDir().toStdString()));
    QVERIFY2(window_->newFromCell(QString::fromStdString(cell)), qPrintable(window_->lastError()));
    const std::string stl = dir_.filePath(QStringLiteral("block.stl")).toStdString();
    demoplan::test::write_box_stl(stl, 80, 60, 40);  // millimetres
    CellPanel* panel = window_->cellPanel();
    QVERIFY2(panel->addPart(QString::fromStdString(stl), 0.001), qPrintable(panel->lastError()));
    QVERIFY(ui::test::waitFor([&] { return !window_->sceneView()->glInfo().isEmpty(); }, 5000));
    Document* doc = window_->document();
    doc->selectObject(0);
    window_->sceneView()->fitToScene();  // frames the selected block
    QTest::qWait(60);

    panel->setMarkerSize(0.02);
    panel->setStickingMarkers(true);
    QVERIFY(panel->stickingMarkers());
    // Click the middle of the block's top face (it rests on one of its faces; the camera looks
    // down on the table).
    const Pose part = doc->displayState().objects.at(0);
    const Eigen::Vector3d half(0.04, 0.03, 0.02);
    const Eigen::Vector3d up = part.linear().transpose() * Eigen::Vector3d::UnitZ();
    int top = 0;
    up.cwiseAbs().maxCoeff(&top);
    Eigen::Vector3d top_centre = Eigen::Vector3d::Zero();
    top_centre[top] = up[top] > 0 ? half[top] : -half[top];
    QPointF px;
    const Eigen::Vector3d c = part * top_centre;
    window_->sceneView()->camera().project(QVector3D(float(c.x()), float(c.y()), float(c.z())), window_->sceneView()->size(), px);
    QTest::mouseClick(window_->sceneView(), Qt::LeftButton, {}, px.toPoint());
    QVERIFY2(doc->cell()->parts[0].markers.size() == 1, qPrintable(panel->lastError()));
    QCOMPARE(panel->markerList()->count(), 1);

    // On a face of the 80 x 60 x 40 mm block, 1 mm in front of it, facing the camera.
    const CellMarker& m = doc->cell()->parts[0].markers[0];
    const Eigen::Vector3d at = m.pose.translation(), n = m.pose.linear().col(2);
    int axis = 0;
    n.cwiseAbs().maxCoeff(&axis);
    QCOMPARE(axis, top);
    QVERIFY2(std::abs(std::abs(n[axis]) - 1.0) < 1e-6, "the marker is not flat on a face of the block");
    QVERIFY2(std::abs(std::abs(at[axis]) - (half[axis] + 0.001)) < 1e-6, qPrintable(QString::number(at[axis])));
    const QVector3D eye = window_->sceneView()->camera().eye();
    const Eigen::Vector3d to_eye = Eigen::Vector3d(eye.x(), eye.y(), eye.z()) - part * at;
    QVERIFY((part.linear() * n).dot(to_eye) > 0);

    window_->sceneView()->camera().zoom(6.0f);  // close enough to see the marker
    window_->sceneView()->update();
    QTest::qWait(60);
    const QString shots = ui::test::artifactDir() + QStringLiteral("/ui");
    QDir().mkpath(shots);
    QVERIFY(window_->grab().save(shots + QStringLiteral("/cell-marker-stuck.png")));
    // Off again: a click selects, nothing is stuck.
    panel->setStickingMarkers(false);
    QTest::mouseClick(window_->sceneView(), Qt::LeftButton, {}, px.toPoint());
    QCOMPARE(doc->cell()->parts[0].markers.size(), size_t(1));
  }

  // The table clicked in the 3D view is chosen in the Cell panel and gets the gizmo; dragging its
  // x arrow moves it along x only, one undo step written to the cell file.
  void theGizmoMovesTheFurnitureClickedInTheView() {
    Document* doc = window_->document();
    QVERIFY(doc->cell());
    int table = -1;
    for (size_t f = 0; f < doc->cell()->furniture.size(); ++f)
      if (doc->cell()->furniture[f].name == "table") table = int(f);
    QVERIFY(table >= 0);
    // A click on the table top, away from the block, chooses it.
    doc->selectObject(-1);
    window_->sceneView()->fitToScene();
    QTest::qWait(60);
    const Pose before = doc->cell()->furniture[size_t(table)].pose;
    const Eigen::Vector3d block = doc->displayState().objects.at(0).translation();
    const Eigen::Vector3d top(before.translation().x(), block.y() > before.translation().y() ? -0.4 : 0.4, 0.75);
    QPointF on_top;
    window_->sceneView()->camera().project(QVector3D(float(top.x()), float(top.y()), float(top.z())),
                                           window_->sceneView()->size(), on_top);
    QTest::mouseClick(window_->sceneView(), Qt::LeftButton, {}, on_top.toPoint());
    QCOMPARE(doc->selectedFurniture(), table);
    QCOMPARE(window_->cellPanel()->selection().kind, CellPanel::Kind::Furniture);
    QCOMPARE(doc->selectedObject(), -1);
    QPointF centre;
    QVERIFY(window_->sceneView()->gizmoCenter(centre));
    QPoint on_arrow;
    bool found = false;
    for (double s = 0.01; s <= 0.5 && !found; s += 0.005) {
      const Eigen::Vector3d p = before.translation() + Eigen::Vector3d(s, 0, 0);
      QPointF px;
      window_->sceneView()->camera().project(QVector3D(float(p.x()), float(p.y()), float(p.z())), window_->sceneView()->size(), px);
      if (window_->sceneView()->gizmoHandleAt(px) == 0) on_arrow = px.toPoint(), found = true;
    }
    QVERIFY(found);
    const int steps = doc->undoStack()->count();
    QTest::mousePress(window_->sceneView(), Qt::LeftButton, {}, on_arrow);
    QTest::mouseMove(window_->sceneView(), on_arrow + QPoint(10, 0));
    QTest::mouseMove(window_->sceneView(), on_arrow + QPoint(40, 3));
    QTest::mouseRelease(window_->sceneView(), Qt::LeftButton, {}, on_arrow + QPoint(40, 3));
    const Pose after = doc->cell()->furniture[size_t(table)].pose;
    QVERIFY((after.translation() - before.translation()).norm() > 1e-3);
    QCOMPARE(after.translation().y(), before.translation().y());
    QCOMPARE(after.translation().z(), before.translation().z());
    QCOMPARE(doc->undoStack()->count(), steps + 1);
    QVERIFY(load_cell(doc->cell()->file).furniture[size_t(table)].pose.isApprox(after));
    QTest::qWait(60);
    QVERIFY(window_->grab().save(ui::test::artifactDir() + QStringLiteral("/ui/cell-furniture-gizmo.png")));
    doc->undoStack()->undo();
    QVERIFY(doc->cell()->furniture[size_t(table)].pose.isApprox(before));
    // Choosing a part takes the gizmo back to the parts.
    window_->cellPanel()->select(CellPanel::Kind::Part, 0);
    QCOMPARE(doc->selectedFurniture(), -1);
  }
};

QTEST_MAIN(TestCellWindow)
#include "test_cell_window.moc"
