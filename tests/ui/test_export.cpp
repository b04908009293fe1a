// The export dialog: times a planned path within the robot's limits, shows the program and its
// duration, saves it, and marks the Export step done; a format that does not fit the robot is
// refused with the reason.
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QDir>
#include <QFileSystemWatcher>
#include <QLabel>
#include <QPlainTextEdit>
#include <QTabWidget>
#include <QTemporaryDir>
#include <QtTest>
#include <nlohmann/json.hpp>

#include "core/export/program_writers.h"
#include "ui/document/document.h"
#include "ui/document/program_export.h"
#include "ui/widgets/export_dialog.h"
#include "ui/widgets/joint_plot_view.h"
#include "ui_test_support.h"

using namespace demoplan;
using namespace demoplan::ui;

class TestExport : public QObject {
  Q_OBJECT
  QTemporaryDir dir_;
  QString project_;

private slots:
  void initTestCase() {
    // A project whose last result is a short path: the arm swings joint 1 out and back.
    Document doc(test::dataDir().toStdString());
    doc.open(test::sampleProject());
    Path path;
    path.task = "shelf_1";
    path.robot = "panda";
    path.robot_pose = 1;
    for (const Joint* j : doc.scene().robot.model.configuration_joints()) path.joint_names.push_back(j->name);
    path.object_ids = doc.demonstration().object_ids;
    const Eigen::VectorXd q0 = doc.initialConfiguration();
    for (double a : {0.0, 0.4, 0.0}) {
      Waypoint w;
      w.q = q0;
      w.q[0] += a;
      w.objects = doc.demonstration().events.front().poses;
      w.state = 0;
      w.state_name = "P0";
      path.waypoints.push_back(w);
    }
    const QString path_file = dir_.filePath(QStringLiteral("swing.path.json"));
    save_path(path_file.toStdString(), path);
    Project p = doc.project();
    ResultSummary r;
    r.path = path_file.toStdString();
    r.solved = r.valid = true;
    r.message = "ok";
    r.demonstration_digest = demonstration_digest(p.demonstration);
    p.result = r;
    project_ = dir_.filePath(QStringLiteral("swing.demoplan"));
    save_project(project_.toStdString(), p);
  }

  void fileNamesFitTheFormats() {
    QCOMPARE(program_writer("krl", "").file_name("shelf 1"), std::string("SHELF_1.src"));
    QCOMPARE(program_writer("sunrise", "").file_name("shelf_1_panda"), std::string("Shelf1Panda.java"));
    QCOMPARE(program_writer("csv", "").file_name("2job"), std::string("job_2job.csv"));
  }

  void previewsAndSaves() {
    Document doc(test::dataDir().toStdString());
    doc.open(project_);
    QVERIFY(doc.planning()->result() && doc.planning()->result()->path);
    ExportDialog dialog(&doc, /*interactive=*/false);
    QCOMPARE(dialog.formatBox()->currentData().toString(), QStringLiteral("franka"));
    QVERIFY2(dialog.last().ok, dialog.last().error.c_str());
    QVERIFY(dialog.last().duration_s > 0.1);
    QVERIFY(dialog.last().check_ok);
    QVERIFY(!dialog.last().limits.empty());
    QVERIFY(dialog.summary()->text().contains(QStringLiteral("Duration")));
    QVERIFY(dialog.preview()->toPlainText().size() > 200);
    // CSV: one row per sample, the arm's joints.
    dialog.formatBox()->setCurrentIndex(dialog.formatBox()->findData(QStringLiteral("csv")));
    QVERIFY(dialog.last().ok);
    QVERIFY(dialog.preview()->toPlainText().contains(QStringLiteral("panda_joint1")));
    const QString out = dir_.filePath(QStringLiteral("swing.csv"));
    QVERIFY(dialog.saveTo(out));
    QVERIFY(QFileInfo(out).size() > 200);
    QCOMPARE(doc.steps()->state(Step::Export).status, StepStatus::Ok);
  }

  void listsEveryRegisteredFormat() {
    Document doc(test::dataDir().toStdString());
    doc.open(project_);
    ExportDialog dialog(&doc, false);
    QCOMPARE(dialog.formatBox()->count(), int(program_writers().size()));
    for (const ProgramWriter* w : program_writers()) {
      const int i = dialog.formatBox()->findData(QString::fromStdString(w->id()));
      QVERIFY2(i >= 0, w->id().c_str());
      QCOMPARE(dialog.formatBox()->itemText(i), QString::fromStdString(w->format().label));
    }
  }

  // The preview is the job's in-memory program: no file appears in the temporary folder or the
  // working directory, whatever the format; only Save writes.
  void previewWritesNoFiles() {
    QTemporaryDir temp, work;
    QVERIFY(temp.isValid() && work.isValid());
    const QByteArray old_tmpdir = qgetenv("TMPDIR");
    const QString old_cwd = QDir::currentPath();
    qputenv("TMPDIR", temp.path().toLocal8Bit());
    QDir::setCurrent(work.path());
    // A folder made and removed again in between leaves it empty: count every change.
    QFileSystemWatcher watcher({temp.path(), work.path()});
    int changes = 0;
    connect(&watcher, &QFileSystemWatcher::directoryChanged, this, [&changes] { ++changes; });
    {
      Document doc(test::dataDir().toStdString());
      doc.open(project_);
      ExportDialog dialog(&doc, false);
      for (int i = 0; i < dialog.formatBox()->count(); ++i) {
        dialog.formatBox()->setCurrentIndex(i);
        if (dialog.last().ok) {
          QVERIFY(!dialog.last().files.empty());
          QVERIFY(dialog.preview()->toPlainText().size() > 200);
        }
      }
      dialog.formatBox()->setCurrentIndex(dialog.formatBox()->findData(QStringLiteral("csv")));
      QVERIFY(dialog.last().ok);
      QVERIFY(dialog.preview()->toPlainText().startsWith(QString::fromStdString(dialog.last().files.front().text)));
    }
    QTest::qWait(200);  // inotify's events
    QCOMPARE(changes, 0);
    QDir::setCurrent(old_cwd);
    if (old_tmpdir.isNull()) qunsetenv("TMPDIR");
    else qputenv("TMPDIR", old_tmpdir);
    const auto entries = QDir::Filter::AllEntries | QDir::Filter::NoDotAndDotDot | QDir::Filter::Hidden;
    QVERIFY2(QDir(temp.path()).entryList(entries).isEmpty(), qPrintable(QDir(temp.path()).entryList(entries).join(' ')));
    QVERIFY2(QDir(work.path()).entryList(entries).isEmpty(), qPrintable(QDir(work.path()).entryList(entries).join(' ')));
  }

  // What the preview shows is what Save writes, byte for byte (KRL: the .src and the .dat).
  void savesWhatThePreviewShows() {
    Document doc(test::dataDir().toStdString());
    doc.open(project_);
    ExportDialog dialog(&doc, false);
    dialog.formatBox()->setCurrentIndex(dialog.formatBox()->findData(QStringLiteral("krl")));
    QVERIFY2(dialog.last().ok, dialog.last().error.c_str());
    const std::vector<ProgramFile> shown = dialog.last().files;
    QCOMPARE(shown.size(), size_t(2));
    QCOMPARE(shown.front().name, std::string("SWING.src"));  // the project's name, as KRL wants it
    QTemporaryDir out;
    QVERIFY(dialog.saveTo(out.filePath(QStringLiteral("SWING.src"))));
    for (const ProgramFile& f : shown) {
      QFile saved(out.filePath(QString::fromStdString(f.name)));
      QVERIFY2(saved.open(QIODevice::ReadOnly), f.name.c_str());
      QCOMPARE(saved.readAll().toStdString(), f.text);
    }
  }

  // The Joints tab: one row of position, velocity and acceleration plots per arm joint, each
  // with the limits the program keeps (following the dialog's percentages) and the rests.
  void jointsViewPlotsEveryArmJoint() {
    Document doc(test::dataDir().toStdString());
    doc.open(project_);
    ExportDialog dialog(&doc, false);
    QVERIFY2(dialog.last().ok, dialog.last().error.c_str());
    QCOMPARE(dialog.tabs()->count(), 2);
    QCOMPARE(dialog.tabs()->tabText(0), QStringLiteral("Program"));
    QCOMPARE(dialog.tabs()->tabText(1), QStringLiteral("Joints"));
    const JointPlotView* view = dialog.jointPlot();
    QCOMPARE(view->curveSets(), 7);  // the Panda's arm; the fingers are commanded apart
    for (int r = 0; r < 7; ++r) QCOMPARE(view->jointNames()[size_t(r)], QStringLiteral("panda_joint%1").arg(r + 1));
    const size_t rests = dialog.last().rests;
    QCOMPARE(rests, size_t(3));  // the ends, and the middle waypoint where joint 1 turns back
    for (int r = 0; r < 7; ++r)
      for (int k = 0; k < 3; ++k) {
        const plot::LinePlot& p = view->plotAt(r, k);
        QCOMPARE(p.curves.size(), size_t(1));
        QCOMPARE(p.curves.front().points.size(), dialog.last().trajectory.samples.size());
        QCOMPARE(p.limits.size(), size_t(2));
        QCOMPARE(p.intervals.size(), rests);
      }
    // Joint 1 swings out by 0.4 rad and back; joint 2 stays.
    auto range = [&](int row) {
      double lo = 1e9, hi = -1e9;
      for (const QPointF& pt : view->plotAt(row, 0).curves.front().points) lo = std::min(lo, pt.y()), hi = std::max(hi, pt.y());
      return hi - lo;
    };
    QVERIFY(std::abs(range(0) - 0.4) < 1e-6);
    QVERIFY(range(1) < 1e-9);
    const double v_limit = view->plotAt(0, 1).limits.front().y;
    QVERIFY(v_limit > 0.5);
    QImage image = view->render(1100);
    QVERIFY(image.height() > 7 * 100);
    image.save(test::artifactDir() + QStringLiteral("/export_joints.png"));
    dialog.tabs()->setCurrentIndex(1);
    dialog.show();
    QVERIFY(QTest::qWaitForWindowExposed(&dialog));
    dialog.grab().save(test::artifactDir() + QStringLiteral("/export_dialog_joints.png"));
    // Half the velocity: the dashed limits follow.
    dialog.findChildren<QDoubleSpinBox*>().front()->setValue(50);
    QVERIFY(dialog.last().ok);
    QCOMPARE(view->curveSets(), 7);
    QVERIFY(std::abs(view->plotAt(0, 1).limits.front().y - 0.5 * v_limit) < 1e-9);
    // No path: a message instead of plots.
    Document empty(test::dataDir().toStdString());
    ExportDialog none(&empty, false);
    QCOMPARE(none.jointPlot()->curveSets(), 0);
  }

  // Franka's trajectory is one long JSON line; the preview indents it (the file stays as it is).
  void previewIndentsOneLineJson() {
    Document doc(test::dataDir().toStdString());
    doc.open(project_);
    ExportDialog dialog(&doc, false);
    QCOMPARE(dialog.formatBox()->currentData().toString(), QStringLiteral("franka"));
    QVERIFY(dialog.last().ok);
    const std::string& file = dialog.last().files.front().text;
    QCOMPARE(std::count(file.begin(), file.end(), '\n'), 1L);
    const QStringList shown = dialog.preview()->toPlainText().split(QLatin1Char('\n'));
    QVERIFY(shown.size() > 100);
    QCOMPARE(shown.front(), QStringLiteral("{"));
    QFile text(test::artifactDir() + QStringLiteral("/export_franka_preview.txt"));
    if (text.open(QIODevice::WriteOnly)) text.write(dialog.preview()->toPlainText().left(4000).toUtf8());
    for (const QString& line : shown) QVERIFY2(line.size() < 400, qPrintable(line.left(80)));
    // The same content.
    QCOMPARE(nlohmann::json::parse(dialog.preview()->toPlainText().toStdString()), nlohmann::json::parse(file));
  }

  void refusesAFormatThatDoesNotFitTheRobot() {
    Document doc(test::dataDir().toStdString());
    doc.open(project_);
    ExportDialog dialog(&doc, false);
    dialog.formatBox()->setCurrentIndex(dialog.formatBox()->findData(QStringLiteral("urscript")));
    QVERIFY(!dialog.last().ok);
    QVERIFY2(dialog.summary()->text().contains(QStringLiteral("6-axis")), qPrintable(dialog.summary()->text()));
    QVERIFY(!dialog.saveTo(dir_.filePath(QStringLiteral("x.script"))));
    QVERIFY(!QFileInfo::exists(dir_.filePath(QStringLiteral("x.script"))));
  }
};

DEMOPLAN_UI_TEST_MAIN(TestExport)
#include "test_export.moc"
