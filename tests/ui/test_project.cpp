// The project file: a project round-trips through save and open unchanged; unreadable,
// foreign and newer files are refused with a message naming the file and the field.
#include <QFile>
#include <QTemporaryDir>
#include <QSignalSpy>
#include <QtTest>

#include "core/error.h"
#include "ui/document/document.h"
#include "core/project/project.h"
#include "ui_test_support.h"

using namespace demoplan;
using namespace demoplan::ui;

namespace {
QByteArray readAll(const QString& f) {
  QFile file(f);
  file.open(QIODevice::ReadOnly);
  return file.readAll();
}
void writeAll(const QString& f, const QByteArray& data) {
  QFile file(f);
  file.open(QIODevice::WriteOnly | QIODevice::Truncate);
  file.write(data);
}
}  // namespace

class TestProject : public QObject {
  Q_OBJECT
private slots:
  void roundTripKeepsEverything() {
    QTemporaryDir dir;
    Document doc(test::dataDir().toStdString());
    doc.open(test::sampleProject());
    // Some edits of every kind the file keeps.
    doc.moveEvent(1, 50);
    Pose T = doc.demoPosesAt(50)[1];
    T.translation().x() += 0.0123;
    doc.setObjectPose(1, 1, T);
    doc.setEventConfidence(2, 0.42);
    PlannerSettings s = doc.planning()->settings();
    s.planner.seed = 7;
    s.planner.time_limit = 12.5;
    s.shortcut = false;
    doc.planning()->setSettings(s);
    doc.setCurrentFrame(33);
    const QString a = dir.filePath(QStringLiteral("a.demoplan"));
    doc.saveAs(a);
    QVERIFY(!doc.isModified());

    Document again(test::dataDir().toStdString());
    again.open(a);
    QCOMPARE(again.currentFrame(), 33);
    QCOMPARE(again.planning()->settings().planner.seed, std::uint64_t(7));
    QCOMPARE(again.planning()->settings().planner.time_limit, 12.5);
    QCOMPARE(again.planning()->settings().shortcut, false);
    QCOMPARE(again.demonstration().events[1].frame, 50);
    QCOMPARE(again.demonstration().events[2].confidence, 0.42);
    QCOMPARE(demonstration_to_json(again.demonstration()), demonstration_to_json(doc.demonstration()));
    QCOMPARE(again.media()->videoPath(), doc.media()->videoPath());  // relative in the file, the same file again
    QCOMPARE(again.media()->cameraPath(), doc.media()->cameraPath());
    QVERIFY(again.media()->video() != nullptr);
    // Saving what was opened writes the same bytes.
    const QString b = dir.filePath(QStringLiteral("b.demoplan"));
    again.saveAs(b);
    QByteArray bytes_a = readAll(a), bytes_b = readAll(b);
    QVERIFY(!bytes_a.isEmpty());
    QCOMPARE(bytes_b, bytes_a);
  }

  void pathsAreRelativeToTheProject() {
    QTemporaryDir dir;
    Document doc(test::dataDir().toStdString());
    doc.open(test::sampleProject());
    const QString sub = dir.filePath(QStringLiteral("jobs/x.demoplan"));
    QDir().mkpath(dir.filePath(QStringLiteral("jobs")));
    doc.saveAs(sub);
    const Json j = read_json_file(sub.toStdString());
    const std::string video = j["video"];
    QVERIFY2(video.rfind("..", 0) == 0 || video[0] == '/', video.c_str());
    QCOMPARE(j["format"].get<std::string>(), std::string(kProjectFormat));
    QCOMPARE(j["version"].get<int>(), kProjectVersion);
    // Opened from there, it finds the same video.
    Document again(test::dataDir().toStdString());
    again.open(sub);
    QVERIFY2(again.media()->video() != nullptr, qPrintable(again.media()->videoError()));
  }

  void refusesBadFiles_data() {
    QTest::addColumn<QByteArray>("content");
    QTest::addColumn<QString>("expected");
    QTest::newRow("not json") << QByteArray("{ this is not json") << QStringLiteral("invalid JSON");
    QTest::newRow("other format") << QByteArray(R"({"format": "demoplan-path", "version": 1})")
                                  << QStringLiteral("not a demoplan project");
    QTest::newRow("newer version") << QByteArray(R"({"format": "demoplan-project", "version": 9})")
                                   << QStringLiteral("unsupported project version 9");
    QTest::newRow("missing scene") << QByteArray(R"({"format": "demoplan-project", "version": 1})")
                                   << QStringLiteral("scene");
  }

  void refusesBadFiles() {
    QFETCH(QByteArray, content);
    QFETCH(QString, expected);
    QTemporaryDir dir;
    const QString f = dir.filePath(QStringLiteral("bad.demoplan"));
    writeAll(f, content);
    Document doc(test::dataDir().toStdString());
    try {
      doc.open(f);
      QFAIL("opened a bad file");
    } catch (const InputError& e) {
      const QString what = QString::fromUtf8(e.what());
      QVERIFY2(what.contains(expected), qPrintable(what));
      QVERIFY2(what.contains(f), qPrintable(what));  // names the file
    }
    QVERIFY(!doc.hasProject());  // nothing half-loaded
  }

  void refusesADemonstrationOfOtherParts() {
    QTemporaryDir dir;
    Json j = read_json_file(test::sampleProject().toStdString());
    j["scene"]["task"] = "tunnel_0";
    const QString f = dir.filePath(QStringLiteral("other.demoplan"));
    writeAll(f, QByteArray::fromStdString(j.dump()));
    Document doc(test::dataDir().toStdString());
    try {
      doc.open(f);
      QFAIL("opened a project whose demonstration does not match its scene");
    } catch (const InputError& e) {
      QVERIFY2(QString::fromUtf8(e.what()).contains(QStringLiteral("demonstration.objects")), e.what());
    }
  }

  void missingVideoIsReportedNotFatal() {
    QTemporaryDir dir;
    Json j = read_json_file(test::sampleProject().toStdString());
    j["video"] = "nowhere.mp4";
    j["camera"] = "";
    const QString f = dir.filePath(QStringLiteral("novideo.demoplan"));
    writeAll(f, QByteArray::fromStdString(j.dump()));
    Document doc(test::dataDir().toStdString());
    doc.open(f);
    QVERIFY(doc.hasProject());
    QCOMPARE(doc.steps()->state(Step::Video).status, StepStatus::Error);
    QVERIFY(doc.steps()->state(Step::Video).message.contains(QStringLiteral("nowhere.mp4")));
  }

  void aCameraOrVideoChangeIsOneUndoStep() {
    Document doc(test::dataDir().toStdString());
    doc.open(test::sampleProject());
    QVERIFY(doc.hasProject());
    QVERIFY(!doc.isModified());
    const std::string camera = doc.media()->cameraFile();
    QVERIFY(doc.media()->camera());
    // An unreadable calibration is still taken (its error shown), and undone back to the good one.
    QTemporaryDir dir;
    const QString bad = dir.filePath(QStringLiteral("bad_camera.json"));
    writeAll(bad, "{\"fx\": 1}");
    QSignalSpy changed(doc.media(), &Media::cameraChanged);
    doc.setMediaFile(Media::File::Camera, bad);
    QCOMPARE(doc.undoStack()->count(), 1);
    QVERIFY(doc.undoStack()->undoText().contains(QStringLiteral("bad_camera.json")));
    QVERIFY(!doc.media()->camera());
    QVERIFY(!doc.media()->cameraError().isEmpty());
    QVERIFY(doc.isModified());
    doc.undoStack()->undo();
    QCOMPARE(doc.media()->cameraFile(), camera);
    QVERIFY(doc.media()->camera());
    QVERIFY(!doc.isModified());  // back where it was opened
    doc.undoStack()->redo();
    QVERIFY(!doc.media()->camera());
    QCOMPARE(changed.count(), 3);
    // No video at all, and back.
    const std::string video = doc.media()->videoFile();
    doc.setMediaFile(Media::File::Video, QString());
    QVERIFY(!doc.media()->video());
    doc.undoStack()->undo();
    QCOMPARE(doc.media()->videoFile(), video);
    QVERIFY(doc.media()->video());
  }
};

DEMOPLAN_UI_TEST_MAIN(TestProject)
#include "test_project.moc"
