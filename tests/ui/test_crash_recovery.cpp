// Crash recovery, proven with real processes: this test runs itself as a child that edits a
// project in a real MainWindow and is killed with SIGKILL, (1) after an autosave, then a new
// window started on the same project must offer the autosave and restore the edit; (2) while it
// saves the project over and over, then the project file must load whole every time (saves are
// atomic: a temporary file renamed over the old one).
#include <QMessageBox>
#include <QProcess>
#include <QPushButton>
#include <QTimer>
#include <csignal>
#include <iostream>

#include "core/project/project.h"
#include "ui/document/document.h"
#include "ui/mainwindow/main_window.h"
#include "ui_test_support.h"

using namespace demoplan;
using namespace demoplan::ui;

namespace {

constexpr int kAutosaveMs = 300;  // the child's autosave interval (the application's: 60 s)

MainWindowOptions childOptions() {
  MainWindowOptions o;
  o.data_dir = test::dataDir().toStdString();
  o.interactive = false;
  o.restore_layout = false;
  o.autosave_interval_ms = kAutosaveMs;
  return o;
}

// Child 1: open, move event 3 to frame 100, wait for the autosave timer, say so, idle.
int childEditAndWait(const QString& project) {
  MainWindow w(childOptions());
  w.show();
  if (!w.openProject(project)) return 3;
  w.document()->moveEvent(3, 100);
  const QString autosave = w.autosavePath();
  if (!test::waitFor([&] { return QFileInfo::exists(autosave); }, 20'000)) return 4;
  std::cout << "autosaved" << std::endl;
  return QApplication::exec();  // until killed
}

// Child 2: open, then edit and save as fast as it can, saying each save.
int childSaveForever(const QString& project) {
  MainWindow w(childOptions());
  if (!w.openProject(project)) return 3;
  for (int k = 0;; ++k) {
    w.document()->moveEvent(3, 60 + k % 40);
    w.document()->save();
    std::cout << "saved " << k << std::endl;
  }
}

}  // namespace

class CrashRecoveryTest : public QObject {
  Q_OBJECT

  QTemporaryDir dir_;

  // A copy of the sample project (with its video and calibration) that the test may change.
  QString copySample() {
    const QDir from = QFileInfo(test::sampleProject()).absoluteDir();
    for (const QString& f : from.entryList(QDir::Files)) QFile::copy(from.filePath(f), dir_.filePath(f));
    return dir_.filePath(QFileInfo(test::sampleProject()).fileName());
  }

  std::unique_ptr<QProcess> startChild(const QString& mode, const QString& project) {
    auto p = std::make_unique<QProcess>();
    p->setProcessChannelMode(QProcess::ForwardedErrorChannel);
    p->start(QCoreApplication::applicationFilePath(), {mode, project});
    return p;
  }

  static bool waitForLine(QProcess& p, const QByteArray& prefix, int timeout_ms) {
    return test::waitFor([&] {
      while (p.canReadLine())
        if (p.readLine().startsWith(prefix)) return true;
      return p.state() == QProcess::NotRunning;
    }, timeout_ms) && p.state() == QProcess::Running;
  }

  static void killHard(QProcess& p) {
    ::kill(static_cast<pid_t>(p.processId()), SIGKILL);
    QVERIFY(p.waitForFinished(10'000));
    QCOMPARE(p.exitStatus(), QProcess::CrashExit);
  }

private slots:
  void killedAfterAnAutosaveTheNextStartOffersItAndRestoresTheEdit() {
    if (test::glUnavailable()) QSKIP("needs an X server (QOpenGLWidget)");
    const QString project = copySample();
    const int frame_before = load_project(project.toStdString()).demonstration.events[3].frame;
    QVERIFY(frame_before != 100);
    auto child = startChild(QStringLiteral("--child-edit"), project);
    QVERIFY2(waitForLine(*child, "autosaved", 60'000), "the child did not autosave");
    killHard(*child);
    // The project file itself was never saved.
    QCOMPARE(load_project(project.toStdString()).demonstration.events[3].frame, frame_before);

    MainWindowOptions o = childOptions();
    o.interactive = true;  // the recovery offer is a dialog
    MainWindow next(o);
    QString offer;
    QTimer clicker;
    clicker.setInterval(20);
    connect(&clicker, &QTimer::timeout, [&] {
      auto* box = qobject_cast<QMessageBox*>(QApplication::activeModalWidget());
      if (!box) return;
      offer = box->text();
      for (QAbstractButton* b : box->buttons())
        if (b->text() == QStringLiteral("Recover")) b->click();
    });
    clicker.start();
    next.startUp(project);  // as `demoplan PROJECT` starts
    clicker.stop();
    QVERIFY2(offer.contains(QFileInfo(project).fileName()), qPrintable(offer));
    QCOMPARE(next.document()->demonstration().events[3].frame, 100);
    QCOMPARE(next.document()->filePath(), QFileInfo(project).absoluteFilePath());
    QVERIFY(next.document()->isModified());  // recovered work is unsaved until the user saves
    QVERIFY(!next.pendingAutosave().has_value());
  }

  void killedWhileSavingTheProjectFileLoadsWhole() {
    if (test::glUnavailable()) QSKIP("needs an X server (QOpenGLWidget)");
    const QString project = copySample();
    int saves = 0;
    for (int round = 0; round < 8; ++round) {
      auto child = startChild(QStringLiteral("--child-save"), project);
      QVERIFY2(waitForLine(*child, "saved", 60'000), "the child did not save");
      QTest::qWait(15 + 23 * round);  // kill at a different point of a save each round
      killHard(*child);
      while (child->canReadLine())
        if (child->readLine().startsWith("saved")) ++saves;
      try {
        const Project p = load_project(project.toStdString());
        QVERIFY(p.demonstration.events.size() > 3);
        const int f = p.demonstration.events[3].frame;
        QVERIFY2(f >= 60 && f < 100, qPrintable(QString::number(f)));
      } catch (const std::exception& e) {
        QFAIL(qPrintable(QStringLiteral("round %1: %2").arg(round).arg(QString::fromUtf8(e.what()))));
      }
    }
    qInfo() << "project file whole after 8 kills during" << saves << "saves or more";
    QVERIFY(saves > 8);
  }
};

int main(int argc, char** argv) {
  if (argc == 3 && (QByteArray(argv[1]) == "--child-edit" || QByteArray(argv[1]) == "--child-save")) {
    // The child shares the parent's environment: settings and autosaves in its temporary home.
    const QString project = QString::fromLocal8Bit(argv[2]);
    const bool edit = QByteArray(argv[1]) == "--child-edit";
    return demoplan::ui::test::withTestApplication(
        argc, argv, [&] { return edit ? childEditAndWait(project) : childSaveForever(project); });
  }
  CrashRecoveryTest test;
  return demoplan::ui::test::runTests(argc, argv, &test);
}

#include "test_crash_recovery.moc"
