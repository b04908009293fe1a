// Edit > Detect Events from Tracks in the real main window (OpenGL: runs under Xvfb): enabled on
// a benchmark project, one undo step, the Part Tracks dock shown under the timeline with its
// frames lined up. Screenshots go to build/test-artifacts/ui/10_tracks.png (the window) and
// 10_tracks_docks.png (the timeline and the tracks: docs/tracks-panel.png); the Edit menu's
// placement from pose estimates, 11_edit_menu.png.
#include <QAction>
#include <QDockWidget>
#include <QElapsedTimer>
#include <QMenu>
#include <QMenuBar>
#include <QUndoStack>
#include <QtTest>

#include "ui/mainwindow/main_window.h"
#include "ui/widgets/part_tracks_panel.h"
#include "ui/widgets/part_tracks_view.h"
#include "ui/widgets/timeline_widget.h"
#include "ui_test_support.h"

using namespace demoplan;
using namespace demoplan::ui;

class TestTracksWindow : public QObject {
  Q_OBJECT
  std::unique_ptr<MainWindow> window_;

  QAction* action(const QString& text) {
    for (QAction* a : window_->findChildren<QAction*>())
      if (a->text() == text) return a;
    return nullptr;
  }

private slots:
  void initTestCase() {
    if (test::glUnavailable()) QSKIP("needs an X server for QOpenGLWidget: run under xvfb-run (test.sh does)");
    MainWindowOptions o;
    o.data_dir = test::dataDir().toStdString();
    o.interactive = false;
    o.restore_layout = false;
    window_ = std::make_unique<MainWindow>(o);
    window_->resize(1280, 800);
    window_->show();
    QVERIFY(QTest::qWaitForWindowExposed(window_.get()));
  }
  void cleanupTestCase() { window_.reset(); }

  void detectsFromTracksAsOneUndoStepAndShowsTheTracks() {
    QAction* detect = action(QStringLiteral("Detect Events from &Tracks"));
    QVERIFY(detect);
    QVERIFY(!detect->isEnabled());  // no project yet
    QVERIFY2(window_->newFromBenchmark(QStringLiteral("shelf_1"), QStringLiteral("panda"), 1), qPrintable(window_->lastError()));
    QVERIFY(detect->isEnabled());
    QVERIFY(!window_->partTracksDock()->isVisible());
    Document* doc = window_->document();
    const Json before = demonstration_to_json(doc->demonstration());
    const int height = window_->height();
    QElapsedTimer clock;
    clock.start();
    detect->trigger();
    qInfo("Detect Events from Tracks took %lld ms on the GUI thread", clock.elapsed());  // for the record, not a limit
    QVERIFY2(window_->lastError().isEmpty(), qPrintable(window_->lastError()));
    QCOMPARE(int(doc->demonstration().events.size()), 4);
    QCOMPARE(doc->undoStack()->count(), 1);
    QVERIFY(window_->partTracksDock()->isVisible());
    PartTracksView* view = window_->partTracksPanel()->view();
    QVERIFY(view->tracks());
    // Under the timeline and as wide: a frame is at the same x in both.
    TimelineWidget* timeline = window_->timelinePanel()->timeline();
    const QPoint in_view = view->mapTo(window_.get(), QPoint(int(view->axis().toX(60)), 0));
    const QPoint in_timeline = timeline->mapTo(window_.get(), QPoint(int(timeline->frameToX(60)), 0));
    QVERIFY2(std::abs(in_view.x() - in_timeline.x()) <= 1, qPrintable(QStringLiteral("%1 vs %2").arg(in_view.x()).arg(in_timeline.x())));
    QVERIFY(in_view.y() > in_timeline.y());
    // On a taller screen the dock opens with room for the position and the angle.
    window_->resize(1400, 1000);
    QVERIFY(test::waitFor([&] { return view->showsAngle(); }, 2000));
    doc->selectEvent(0);
    doc->setCurrentFrame(doc->demonstration().events[0].frame + 8);
    QTest::qWait(100);  // let the GL view repaint
    qInfo("window %d px high before, %d after; tracks dock %d", height, window_->height(), window_->partTracksDock()->height());
    const QString shots = test::artifactDir() + QStringLiteral("/ui");
    QDir().mkpath(shots);
    QVERIFY(window_->grab().save(shots + QStringLiteral("/10_tracks.png")));
    // The timeline and the tracks alone, for docs/tracks-panel.png.
    const QRect docks = window_->timelinePanel()->parentWidget()->geometry().united(window_->partTracksDock()->geometry());
    QVERIFY(window_->grab(docks).save(shots + QStringLiteral("/10_tracks_docks.png")));
    doc->undoStack()->undo();
    QCOMPARE(demonstration_to_json(doc->demonstration()), before);
  }

  // Edit > Place Parts from Pose Estimates is in the Edit menu, with the other placement actions,
  // and enabled on a project (its work is tested in test_start_poses). The open menu:
  // build/test-artifacts/ui/11_edit_menu.png.
  void theEditMenuOffersToPlaceThePartsFromPoseEstimates() {
    QAction* estimates = action(QStringLiteral("Place Parts &from Pose Estimates..."));
    QVERIFY(estimates);
    QVERIFY(estimates->isEnabled());
    QMenu* edit = nullptr;
    for (QAction* a : window_->menuBar()->actions())
      if (a->text() == QStringLiteral("&Edit")) edit = a->menu();
    QVERIFY(edit);
    QVERIFY(edit->actions().contains(estimates));
    edit->popup(window_->mapToGlobal(QPoint(60, 30)));
    QVERIFY(QTest::qWaitForWindowExposed(edit));
    QVERIFY(edit->actionGeometry(estimates).isValid());
    const QString shots = test::artifactDir() + QStringLiteral("/ui");
    QDir().mkpath(shots);
    QVERIFY(edit->grab().save(shots + QStringLiteral("/11_edit_menu.png")));
    edit->hide();
  }
};

DEMOPLAN_UI_TEST_MAIN(TestTracksWindow)
#include "test_tracks_window.moc"
