// The placement search in the real main window (OpenGL: run under xvfb-run): Plan > Where to Put
// the Robot brings the Placement panel forward, a search over the sample's region draws every
// candidate on the 3D view's floor as the heat map colours it, and a new project clears them.
// Screenshot in build/test-artifacts/ui/.
#include <QDir>
#include <QDockWidget>
#include <QSpinBox>
#include <QtTest>

#include "ui/mainwindow/main_window.h"
#include "ui/view3d/scene_view.h"
#include "ui/widgets/placement_panel.h"
#include "ui_test_support.h"

using namespace demoplan;
using namespace demoplan::ui;

class TestPlacementWindow : public QObject {
  Q_OBJECT
private slots:
  void theSearchIsDrawnOnTheFloor() {
    if (ui::test::glUnavailable()) QSKIP("needs an X server for QOpenGLWidget: run under xvfb-run (test.sh does)");
    MainWindowOptions o;
    o.data_dir = ui::test::dataDir().toStdString();
    o.interactive = false;
    o.restore_layout = false;
    o.sample_project = ui::test::sampleProject();
    MainWindow window(o);
    window.resize(1400, 900);
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    QVERIFY2(window.openSample(), qPrintable(window.lastError()));
    Document* doc = window.document();
    window.placementPanel()->samplesBox()->setValue(40);
    window.placementPanel()->seedsBox()->setValue(1);
    QAction* where = nullptr;
    for (QAction* a : window.findChildren<QAction*>())
      if (a->text().startsWith(QStringLiteral("&Where to Put the Robot"))) where = a;
    QVERIFY(where != nullptr);
    where->trigger();
    QVERIFY(window.placementDock()->isVisible());
    window.placementPanel()->search();
    QVERIFY(doc->placement()->isRunning());
    QVERIFY(ui::test::waitFor([&] { return !doc->placement()->isRunning(); }, 180000));
    QCOMPARE(window.sceneView()->placementSquareCount(), 40u);
    QVERIFY(doc->placement()->best() != nullptr);
    QTest::qWait(100);
    const QString shots = ui::test::artifactDir() + QStringLiteral("/ui");
    QDir().mkpath(shots);
    QVERIFY(window.grab().save(shots + QStringLiteral("/placement-window.png")));
    QVERIFY2(window.openSample(), qPrintable(window.lastError()));
    QCOMPARE(window.sceneView()->placementSquareCount(), 0u);
  }
};

DEMOPLAN_UI_TEST_MAIN(TestPlacementWindow)
#include "test_placement_window.moc"
