// The operator's job end to end in the real main window (OpenGL: needs an X server, run under
// xvfb-run): open the sample, select a part in the 3D view and correct its pose (fields and
// gizmo), break and repair a rule, plan while the trees grow, check the validator's verdict,
// play the path back, save, reopen. Screenshots of every stage go to build/test-artifacts/.
#include <QComboBox>
#include <QDockWidget>
#include <QDoubleSpinBox>
#include <QPlainTextEdit>
#include <QLabel>
#include <QPushButton>
#include <QSlider>
#include <QTableWidget>
#include <QUndoStack>
#include <QtTest>

#include "perception/events/tracks_demonstration.h"
#include "ui/document/demo_poses.h"
#include "ui/mainwindow/main_window.h"
#include "ui/view3d/scene_view.h"
#include "ui/widgets/export_dialog.h"
#include "ui/widgets/part_tracks_panel.h"
#include "ui/widgets/part_tracks_view.h"
#include "ui/widgets/planner_panel.h"
#include "ui/widgets/pose_editor.h"
#include "ui/widgets/result_panel.h"
#include "ui/widgets/step_bar.h"
#include "ui/widgets/timeline_widget.h"
#include "ui/widgets/transport.h"
#include "ui/widgets/video_panel.h"
#include "ui_test_support.h"

using namespace demoplan;
using namespace demoplan::ui;

class TestEndToEnd : public QObject {
  Q_OBJECT
  std::unique_ptr<MainWindow> window_;
  QString shots_;

  Document* doc() { return window_->document(); }
  void shoot(const QString& name) {
    QTest::qWait(60);  // let the GL view repaint
    const QString file = shots_ + QLatin1Char('/') + name + QStringLiteral(".png");
    QVERIFY2(window_->grab().save(file), qPrintable(file));
    qInfo("screenshot %s", qPrintable(file));
  }
  // Pixel of a world point in the 3D view.
  QPoint pixelOf(const Eigen::Vector3d& p) {
    QPointF px;
    window_->sceneView()->camera().project(QVector3D(float(p.x()), float(p.y()), float(p.z())), window_->sceneView()->size(), px);
    return px.toPoint();
  }
  Pose poseAt(int event, int object) {
    return world_pose_at_event(doc()->scene(), doc()->demonstration(), size_t(event), object, doc()->initialConfiguration());
  }

private slots:
  void initTestCase() {
    if (test::glUnavailable()) QSKIP("needs an X server for QOpenGLWidget: run under xvfb-run (test.sh does)");
    shots_ = test::artifactDir() + QStringLiteral("/ui");
    QDir().mkpath(shots_);
    MainWindowOptions o;
    o.data_dir = test::dataDir().toStdString();
    o.sample_project = test::sampleProject();
    o.interactive = false;
    o.restore_layout = false;
    window_ = std::make_unique<MainWindow>(o);
    window_->resize(1280, 800);
    window_->show();
    QVERIFY(QTest::qWaitForWindowExposed(window_.get()));
    window_->activateWindow();
    QVERIFY(QTest::qWaitForWindowActive(window_.get()));  // keyboard shortcuts need it
  }
  void cleanupTestCase() { window_.reset(); }

  void opensTheSampleOnFirstStart() {
    window_->startUp(QString());
    QVERIFY2(doc()->hasProject(), qPrintable(window_->lastError()));
    QVERIFY(doc()->isTemplate());  // Save asks where
    QVERIFY(doc()->media()->video() != nullptr);
    QVERIFY(doc()->media()->camera() != nullptr);
    QVERIFY(test::waitFor([&] { return !window_->sceneView()->glInfo().isEmpty(); }, 5000));
    qInfo("3D view: %s", qPrintable(window_->sceneView()->glInfo()));
    QVERIFY(!window_->sceneView()->glFailed());
    QCOMPARE(window_->stepBar()->state(Step::Video).status, StepStatus::Ok);
    QCOMPARE(window_->stepBar()->state(Step::Events).status, StepStatus::Ok);
    QCOMPARE(window_->stepBar()->state(Step::Poses).status, StepStatus::Ok);
    // The video shows the parts' outlines where the demonstration knows their poses: at the
    // events and at rest, not in the hand between a grasp and its release.
    auto outlines = [&] {
      int n = 0;
      for (const auto& p : window_->videoPanel()->frameView()->outlines()) n += !p.isEmpty();
      return n;
    };
    doc()->setCurrentFrame(30);  // YCBV_05 in the hand
    QCOMPARE(outlines(), 1);
    doc()->setCurrentFrame(48);  // its release
    QCOMPARE(outlines(), 2);
    QVERIFY(!window_->videoPanel()->frameView()->image().isNull());
    shoot(QStringLiteral("01-sample-opened"));
    // The keyboard drives the video: arrows, Shift+arrows, Home/End, J/K/L, Space.
    window_->sceneView()->setFocus();
    QTest::keyClick(window_.get(), Qt::Key_Home);
    QCOMPARE(doc()->currentFrame(), 0);
    QTest::keyClick(window_.get(), Qt::Key_Right);
    QCOMPARE(doc()->currentFrame(), 1);
    QTest::keyClick(window_.get(), Qt::Key_Right, Qt::ShiftModifier);
    QCOMPARE(doc()->currentFrame(), 31);
    QTest::keyClick(window_.get(), Qt::Key_Left);
    QCOMPARE(doc()->currentFrame(), 30);
    QTest::keyClick(window_.get(), Qt::Key_L);
    QVERIFY(window_->transport()->isPlaying());
    QVERIFY(test::waitFor([&] { return doc()->currentFrame() >= 36; }, 3000));
    QTest::keyClick(window_.get(), Qt::Key_K);
    QVERIFY(!window_->transport()->isPlaying());
    const int paused_at = doc()->currentFrame();
    QTest::keyClick(window_.get(), Qt::Key_J);
    QVERIFY(test::waitFor([&] { return doc()->currentFrame() < paused_at; }, 3000));
    QTest::keyClick(window_.get(), Qt::Key_Space);  // pauses
    QVERIFY(!window_->transport()->isPlaying());
    QTest::keyClick(window_.get(), Qt::Key_End);
    QCOMPARE(doc()->currentFrame(), doc()->frameCount() - 1);
    QVERIFY(!window_->videoPanel()->frameView()->image().isNull());
    qInfo("3D paint: %.1f ms", window_->sceneView()->lastPaintMs());
  }

  void selectAndCorrectAPose() {
    doc()->selectEvent(1);  // release of YCBV_05: where it is put down
    doc()->selectObject(-1);
    QTest::qWait(30);
    // Click the part in the 3D view.
    const Pose T = poseAt(1, 1);
    const QPoint px = pixelOf(T * Eigen::Vector3d(0, 0, 0.08));
    QTest::mouseClick(window_->sceneView(), Qt::LeftButton, {}, px);
    QCOMPARE(doc()->selectedObject(), 1);
    // Type a correction. Keys typed into a field stay there: they do not scrub the video.
    QDoubleSpinBox* y = window_->poseEditor()->field(1);
    y->setFocus();
    const int frame = doc()->currentFrame();
    QTest::keyClick(y, Qt::Key_Right);
    QTest::keyClick(y, Qt::Key_Space);
    QTest::keyClick(y, Qt::Key_L);
    QCOMPARE(doc()->currentFrame(), frame);
    QVERIFY(!window_->transport()->isPlaying());
    y->setValue(y->value() - 20.0);
    QVERIFY(std::abs(poseAt(1, 1).translation().y() - (T.translation().y() - 0.020)) < 1e-4);
    // Drag the gizmo's x arrow.
    QPointF centre;
    QVERIFY(window_->sceneView()->gizmoCenter(centre));
    const Pose before_drag = poseAt(1, 1);
    QPoint on_arrow;
    bool found = false;
    for (double s = 0.01; s <= 0.3 && !found; s += 0.005) {
      const QPoint p = pixelOf(before_drag.translation() + Eigen::Vector3d(s, 0, 0));
      if (window_->sceneView()->gizmoHandleAt(p) == 0) on_arrow = p, found = true;
    }
    QVERIFY(found);
    QTest::mousePress(window_->sceneView(), Qt::LeftButton, {}, on_arrow);
    QTest::mouseMove(window_->sceneView(), on_arrow + QPoint(10, 0));
    QTest::mouseMove(window_->sceneView(), on_arrow + QPoint(30, 4));
    shoot(QStringLiteral("02-pose-corrected-gizmo-drag"));
    QTest::mouseRelease(window_->sceneView(), Qt::LeftButton, {}, on_arrow + QPoint(30, 4));
    const Pose after_drag = poseAt(1, 1);
    QVERIFY((after_drag.translation() - before_drag.translation()).norm() > 1e-3);
    QVERIFY(std::abs(after_drag.translation().y() - before_drag.translation().y()) < 1e-9);  // only along x
    QVERIFY(std::abs(after_drag.translation().z() - before_drag.translation().z()) < 1e-9);
    // Both corrections undo, back to the sample.
    doc()->undoStack()->undo();
    doc()->undoStack()->undo();
    QVERIFY((poseAt(1, 1).translation() - T.translation()).norm() < 1e-9);
    QVERIFY(!doc()->isModified());
  }

  void aBrokenRuleIsShownAndUndone() {
    doc()->removeEvent(2);  // the grasp of YCBV_02: its release has no grasp
    QCOMPARE(window_->stepBar()->state(Step::Events).status, StepStatus::Error);
    QVERIFY(window_->stepBar()->state(Step::Events).message.contains(QStringLiteral("release without a grasp")));
    QVERIFY(!window_->plannerPanel()->planButton()->isEnabled());
    window_->timelinePanel()->jumpToIssue(0);
    shoot(QStringLiteral("03-broken-rule"));
    QTest::keyClick(window_.get(), Qt::Key_Z, Qt::ControlModifier);
    QCOMPARE(window_->stepBar()->state(Step::Events).status, StepStatus::Ok);
    QVERIFY(window_->plannerPanel()->planButton()->isEnabled());
  }

  void planWhileTheTreesGrow() {
    doc()->selectObject(-1);
    doc()->selectEvent(-1);
    PlannerSettings settings = doc()->planning()->settings();
    settings.planner.seed = 2;  // solves the sample in a few seconds
    doc()->planning()->setSettings(settings);
    test::StallMeter meter;
    meter.start();
    QTest::keyClick(window_.get(), Qt::Key_F5);
    QVERIFY(doc()->planning()->runner()->isRunning());
    QVERIFY(test::waitFor([&] { return window_->sceneView()->treeEdgeCount() > 150 || !doc()->planning()->runner()->isRunning(); }, 20000));
    double stall = meter.stop();
    if (doc()->planning()->runner()->isRunning()) shoot(QStringLiteral("04-planning-trees-growing"));  // (a blocking grab)
    meter.start();
    double finished_at = -1;
    QMetaObject::Connection c = connect(doc()->planning()->runner(), &PlanRunner::finished, this, [&] { finished_at = meter.elapsedMs(); });
    QVERIFY(test::waitFor([&] { return !doc()->planning()->runner()->isRunning(); }, 60000));
    QTest::qWait(100);
    disconnect(c);
    qInfo("stall before the screenshot %.1f ms; after: %.1f ms ending at %.0f ms, planning finished at %.0f ms", stall,
          meter.stop(), meter.maxGapAt(), finished_at);
    stall = std::max(stall, meter.stop());
    qInfo("longest event-loop stall while planning with the 3D view: %.1f ms; %zu tree edges drawn", stall,
          window_->sceneView()->treeEdgeCount());
    // Planning never holds the GUI thread for the search (seconds); the longest stall itself is
    // bench_gui_latency's figure (43.9 ms with llvmpipe), not a unit test's.
    QVERIFY2(stall < 1000.0, qPrintable(QStringLiteral("event loop stalled %1 ms").arg(stall)));
    QVERIFY(window_->sceneView()->treeEdgeCount() > 0);
    QVERIFY(window_->sceneView()->treeRootCount() > 0);
    const PlanResultData* r = doc()->planning()->result();
    QVERIFY(r != nullptr);
    QVERIFY2(r->summary.solved, r->summary.message.c_str());
    QVERIFY2(r->summary.valid, r->summary.message.c_str());
    QCOMPARE(window_->stepBar()->state(Step::Plan).status, StepStatus::Ok);
    QVERIFY(window_->resultPanel()->verdictLabel()->text().contains(QStringLiteral("Valid path")));
    QVERIFY(window_->resultPanel()->waypointTable()->rowCount() >= 4);
    shoot(QStringLiteral("05-planned-trees"));
    {
      QElapsedTimer t;
      t.start();
      for (int i = 0; i < 10; ++i) {
        window_->sceneView()->update();
        QTest::qWait(1);
        window_->sceneView()->repaint();
      }
      qInfo("3D view repaint, idle: %.1f ms each", t.elapsed() / 10.0);
      t.start();
      for (int i = 0; i < 10; ++i) window_->repaint();
      qInfo("window repaint, idle: %.1f ms each", t.elapsed() / 10.0);
    }
  }

  void playTheResultBack() {
    QTableWidget* table = window_->resultPanel()->waypointTable();
    QStringList actions;
    for (int k = 0; k < table->rowCount(); ++k) actions << table->item(k, 1)->text();
    for (const char* a : {"approach", "grasp", "carry", "release"})
      QVERIFY2(actions.contains(QLatin1String(a)), qPrintable(actions.join(QLatin1Char(' '))));
    // Scrub to the middle of the first carry: the part travels with the gripper.
    const int carry = int(actions.indexOf(QStringLiteral("carry")));
    const double t0 = doc()->planning()->interpolator()->waypoint_parameter(size_t(carry));
    const double t1 = doc()->planning()->interpolator()->waypoint_parameter(size_t(carry + 1));
    window_->resultPanel()->slider()->setValue(int((t0 + t1) / 2 * 1000));
    QCOMPARE(doc()->displayMode(), Document::DisplayMode::Result);
    const SceneState mid = doc()->displayState();
    const SceneState start = doc()->planning()->interpolator()->at(0.0);
    double moved = 0;
    for (size_t o = 0; o < mid.objects.size(); ++o)
      moved = std::max(moved, (mid.objects[o].translation() - start.objects[o].translation()).norm());
    QVERIFY(moved > 0.01);
    shoot(QStringLiteral("06-playback-carrying"));
    // Play: time advances, then Space pauses.
    QTest::keyClick(window_.get(), Qt::Key_Space);
    QVERIFY(window_->resultPanel()->isPlaying());
    const double t_before = doc()->playbackT();
    QTest::qWait(200);
    QVERIFY(doc()->playbackT() > t_before);
    QTest::keyClick(window_.get(), Qt::Key_Space);
    QVERIFY(!window_->resultPanel()->isPlaying());
  }

  void exportTheProgram() {
    ExportDialog* dialog = window_->showExportDialog();
    QVERIFY(dialog != nullptr);
    QCOMPARE(dialog->formatBox()->currentData().toString(), QStringLiteral("franka"));  // the Panda's controller
    QVERIFY(QTest::qWaitForWindowExposed(dialog));
    const QString shot = shots_ + QStringLiteral("/08-export-dialog.png");
    if (!dialog->last().ok) {
      // The exporters refuse some paths (a known core/trajectory issue): the dialog must say why.
      qWarning("export refused: %s", dialog->last().error.c_str());
      QVERIFY(dialog->summary()->text().contains(QStringLiteral("Cannot export")));
      dialog->grab().save(shot);
      dialog->close();
      return;
    }
    QVERIFY(dialog->last().duration_s > 0);
    QVERIFY(dialog->preview()->toPlainText().contains(QStringLiteral("franka")));
    QVERIFY(dialog->summary()->text().contains(QStringLiteral("Duration")));
    dialog->formatBox()->setCurrentIndex(dialog->formatBox()->findData(QStringLiteral("csv")));
    QVERIFY(dialog->last().ok);
    QVERIFY(dialog->preview()->toPlainText().size() > 100);
    QVERIFY(dialog->grab().save(shot));
    const QString out = shots_ + QStringLiteral("/end_to_end.csv");
    QFile::remove(out);
    QVERIFY(dialog->saveTo(out));
    QVERIFY(QFileInfo(out).size() > 100);
    QCOMPARE(doc()->steps()->state(Step::Export).status, StepStatus::Ok);
    dialog->close();
  }

  void saveAndReopen() {
    const QString file = shots_ + QStringLiteral("/end_to_end.demoplan");
    QFile::remove(file);
    QVERIFY2(window_->saveAs(file), qPrintable(window_->lastError()));
    QVERIFY(QFileInfo::exists(shots_ + QStringLiteral("/end_to_end.path.json")));
    const Json demo = demonstration_to_json(doc()->demonstration());
    const ResultSummary summary = doc()->planning()->result()->summary;
    QVERIFY(window_->openProject(file));
    QCOMPARE(demonstration_to_json(doc()->demonstration()), demo);
    QVERIFY(doc()->planning()->result() != nullptr);
    QVERIFY(doc()->planning()->result()->path.has_value());
    QCOMPARE(doc()->planning()->result()->summary.valid, summary.valid);
    QCOMPARE(doc()->planning()->result()->summary.planning_time_s, summary.planning_time_s);
    QVERIFY(doc()->planning()->interpolator() != nullptr);
    QVERIFY(!doc()->planning()->resultStale());
    QCOMPARE(window_->recentFiles().value(0), QFileInfo(file).absoluteFilePath());
    doc()->setPlaybackT(0.35);
    shoot(QStringLiteral("07-reopened"));
    // A file that cannot be read: a clear message, the open project stays.
    const QString bad = shots_ + QStringLiteral("/bad.demoplan");
    QFile f(bad);
    QVERIFY(f.open(QIODevice::WriteOnly | QIODevice::Truncate));
    f.write("{\"format\": \"demoplan-project\", \"version\": 1, \"scene\": {\"task\": \"shelf_1\"}}");
    f.close();
    QVERIFY(!window_->openProject(bad));
    QVERIFY2(window_->lastError().contains(QStringLiteral("scene.robot")), qPrintable(window_->lastError()));
    QCOMPARE(doc()->filePath(), QFileInfo(file).absoluteFilePath());
  }

  void autosaveWritesARecoverableCopy() {
    doc()->moveEvent(3, 100);
    QVERIFY(doc()->isModified());
    window_->autosaveNow();
    const QString autosave = window_->autosavePath();
    QVERIFY(QFileInfo::exists(autosave));
    // As after a crash: the next session finds the autosave and recovers it.
    {
      MainWindowOptions o;
      o.data_dir = test::dataDir().toStdString();
      o.interactive = false;
      o.restore_layout = false;
      MainWindow next(o);
      const auto pending = next.pendingAutosave();
      QVERIFY(pending.has_value());
      QCOMPARE(pending->origin, doc()->filePath());
      QVERIFY(next.recoverAutosave(*pending));
      QCOMPARE(next.document()->demonstration().events[3].frame, 100);
      QCOMPARE(next.document()->filePath(), doc()->filePath());  // Save goes to the real file
      QVERIFY(next.document()->isModified());
      QVERIFY(next.document()->media()->video() != nullptr);  // relative paths resolved from the autosave folder
      QVERIFY(!QFileInfo::exists(autosave));
    }
    window_->autosaveNow();
    QVERIFY(QFileInfo::exists(autosave));
    QVERIFY(window_->save());
    QVERIFY(!QFileInfo::exists(autosave));  // a real save removes it
  }

  void theLayoutComesBackOnTheNextStart() {
    auto* history = window_->findChild<QDockWidget*>(QStringLiteral("HistoryDock"));
    auto* video = window_->findChild<QDockWidget*>(QStringLiteral("VideoDock"));
    QVERIFY(history && video);
    video->hide();  // the operator closed the video panel
    QVERIFY(window_->close());
    window_.reset();
    MainWindowOptions o;
    o.data_dir = test::dataDir().toStdString();
    o.sample_project = test::sampleProject();
    o.interactive = false;
    o.restore_layout = true;
    window_ = std::make_unique<MainWindow>(o);
    window_->show();
    QVERIFY(QTest::qWaitForWindowExposed(window_.get()));
    window_->activateWindow();
    QVERIFY(QTest::qWaitForWindowActive(window_.get()));
    QVERIFY(window_->findChild<QDockWidget*>(QStringLiteral("VideoDock"))->isHidden());
    QVERIFY(!window_->findChild<QDockWidget*>(QStringLiteral("TimelineDock"))->isHidden());
    // ...and the last project opens again.
    window_->startUp(QString());
    QCOMPARE(window_->document()->filePath(), QFileInfo(shots_ + QStringLiteral("/end_to_end.demoplan")).absoluteFilePath());
  }

  void detectTheEventsInTheVideo() {
    window_->findChild<QDockWidget*>(QStringLiteral("VideoDock"))->show();
    QTest::keyClick(window_.get(), Qt::Key_D, Qt::ControlModifier);
    QVERIFY(doc()->detection()->runner()->isRunning());
    QVERIFY(test::waitFor([&] { return !doc()->detection()->runner()->isRunning(); }, 30000));
    QCOMPARE(int(doc()->demonstration().events.size()), 4);
    QCOMPARE(window_->stepBar()->state(Step::Events).status == StepStatus::Error, false);
    qInfo("after detection: events %s; poses %s", qPrintable(window_->stepBar()->state(Step::Events).message),
          qPrintable(window_->stepBar()->state(Step::Poses).message));
    doc()->selectEvent(2);
    shoot(QStringLiteral("09-events-detected"));
    // What the tracker measured stays for the Part Tracks panel: every part's track, each frame
    // with its confidence, cut into rests and carries.
    TrackDetection* measured = doc()->trackDetection();
    QVERIFY(measured->fromVideo());
    const auto tracks = measured->tracks();
    QVERIFY(tracks);
    const Demonstration& d = doc()->demonstration();
    for (const std::string& id : d.object_ids) {
      const int row = tracks->tracks.object_index(id);
      QVERIFY2(row >= 0, id.c_str());
      int seen = 0;
      for (const auto& s : tracks->tracks.samples[size_t(row)])
        if (s.valid) {
          ++seen;
          QVERIFY2(s.confidence > 0 && s.confidence <= 1, id.c_str());
        }
      QVERIFY2(seen > tracks->tracks.frames / 2, id.c_str());
    }
    // The part grasped at the selected event is carried from there in its track.
    const ContactEvent& grasp = d.events[2];
    QCOMPARE(grasp.type, EventType::Grasp);
    const int row = tracks->tracks.object_index(d.object_ids[size_t(grasp.object)]);
    bool carried = false;
    for (const auto& s : tracks->segmentation.objects[size_t(row)].segments)
      carried = carried || (s.kind == perception::SegmentKind::Carry && std::abs(s.first - grasp.frame) <= 3);
    QVERIFY(carried);
    window_->findChild<QDockWidget*>(QStringLiteral("PartTracksDock"))->show();
    auto* panel = window_->findChild<PartTracksPanel*>();
    QVERIFY(panel);
    QVERIFY(test::waitFor([&] { return panel->view()->row() == row; }, 2000));
    QVERIFY2(panel->summaryLabel()->text().startsWith(QStringLiteral("From the video (marker tracker): ")),
             qPrintable(panel->summaryLabel()->text()));
    const int mid = (grasp.frame + d.events[3].frame) / 2;
    QCOMPARE(panel->view()->confidenceColor(mid).isValid(), true);
    QVERIFY2(panel->view()->toolTipAt(panel->view()->axis().toX(mid)).contains(QStringLiteral("confidence")),
             qPrintable(panel->view()->toolTipAt(panel->view()->axis().toX(mid))));
    shoot(QStringLiteral("10-video-tracks"));
    window_->findChild<QDockWidget*>(QStringLiteral("PartTracksDock"))->hide();
    doc()->undoStack()->undo();
  }
};

DEMOPLAN_UI_TEST_MAIN(TestEndToEnd)
#include "test_end_to_end.moc"
