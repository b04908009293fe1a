// The bad-input corpus (tests/data/bad) through the desktop application's open path: a bad project
// (truncated, or a broken demonstration) is refused with a message naming the file and the field,
// and the project that was open stays open, unchanged; a good project that names a bad video or
// camera opens, with the error naming the bad file (the Video step shows it); interactively the
// refusal is an error dialog.
#include <QApplication>
#include <QFile>
#include <QMessageBox>
#include <QStatusBar>
#include <QTimer>
#include <QtTest>

#include <nlohmann/json.hpp>

#include "core/demo/demonstration.h"
#include "ui/document/document.h"
#include "ui/document/media.h"
#include "ui/mainwindow/main_window.h"
#include "ui_test_support.h"

using namespace demoplan;
using namespace demoplan::ui;
using Json = nlohmann::json;

namespace {
const QString kCorpus = QStringLiteral(DEMOPLAN_BAD_CORPUS);

QByteArray readAll(const QString& f) {
  QFile file(f);
  if (!file.open(QIODevice::ReadOnly)) return {};
  return file.readAll();
}
void writeAll(const QString& f, const QByteArray& data) {
  QFile file(f);
  QVERIFY(file.open(QIODevice::WriteOnly | QIODevice::Truncate));
  file.write(data);
}

struct Entry {
  QString file, gui;
  QStringList expect;  // "{file}" expanded
};
}  // namespace

class TestBadCorpusGui : public QObject {
  Q_OBJECT
private slots:
  void initTestCase() {
    if (test::glUnavailable()) QSKIP("needs an X server for QOpenGLWidget: run under xvfb-run (test.sh does)");
    const Json manifest = Json::parse(readAll(kCorpus + QStringLiteral("/manifest.json")).toStdString());
    for (const auto& e : manifest.at("entries")) {
      if (!e.contains("gui")) continue;
      Entry x;
      x.file = kCorpus + QLatin1Char('/') + QString::fromStdString(e.at("file").get<std::string>());
      x.gui = QString::fromStdString(e.at("gui").get<std::string>());
      for (const auto& p : e.at("expect")) {
        const QString part = QString::fromStdString(p.get<std::string>());
        if (part != QLatin1String("{file}")) x.expect << part;
      }
      entries_.push_back(x);
    }
    QVERIFY(dir_.isValid());
    // The good project: a copy of the sample with its video, camera and marker scene.
    const QString sample = QFileInfo(test::sampleProject()).absolutePath();
    for (const char* f : {"video.mp4", "camera.json", "markers.json"})
      QVERIFY(QFile::copy(sample + QLatin1Char('/') + QLatin1String(f), dir_.filePath(QLatin1String(f))));
    good_ = dir_.filePath(QStringLiteral("good.demoplan"));
    QVERIFY(QFile::copy(test::sampleProject(), good_));
    good_json_ = Json::parse(readAll(good_).toStdString());

    MainWindowOptions o;
    o.data_dir = test::dataDir().toStdString();
    o.interactive = false;
    o.restore_layout = false;
    window_ = std::make_unique<MainWindow>(o);
    QVERIFY2(window_->openProject(good_), qPrintable(window_->lastError()));
    open_path_ = window_->document()->filePath();
    open_demo_ = demonstration_to_json(window_->document()->demonstration());
  }
  void cleanupTestCase() { window_.reset(); }

  void corpusHasFilesForTheOpenPath() {
    int projects = 0, demos = 0, videos = 0, cameras = 0;
    for (const auto& e : entries_) {
      projects += e.gui == QLatin1String("project");
      demos += e.gui == QLatin1String("demonstration");
      videos += e.gui == QLatin1String("video");
      cameras += e.gui == QLatin1String("camera");
    }
    QCOMPARE(projects, 13);  // ten truncations, a NaN and a non-rigid pose, a part placed again not in the scene
    QVERIFY(demos >= 3);
    QVERIFY(videos >= 5);
    QVERIFY(cameras >= 4);
  }

  // Truncated and broken project files: refused, the message names the file and the field, the
  // open project is the same file with the same demonstration and no edits.
  void badProjectsAreRefusedAndTheOpenProjectStays() {
    int tried = 0;
    for (const auto& e : entries_) {
      QString file;
      if (e.gui == QLatin1String("project")) {
        file = e.file;
      } else if (e.gui == QLatin1String("demonstration")) {
        // The good project with this demonstration in it.
        Json j = good_json_;
        j["demonstration"] = Json::parse(readAll(e.file).toStdString());
        file = dir_.filePath(QFileInfo(e.file).completeBaseName() + QStringLiteral(".demoplan"));
        writeAll(file, QByteArray::fromStdString(j.dump(1)));
      } else {
        continue;
      }
      ++tried;
      QVERIFY2(!window_->openProject(file), qPrintable(file));
      const QString error = window_->lastError();
      QVERIFY2(error.contains(file), qPrintable(file + QStringLiteral(": ") + error));
      for (const auto& part : e.expect) QVERIFY2(error.contains(part), qPrintable(part + QStringLiteral(" not in: ") + error));
      QVERIFY2(window_->statusBar()->currentMessage().contains(file), qPrintable(window_->statusBar()->currentMessage()));
      QCOMPARE(window_->document()->filePath(), open_path_);
      QVERIFY(demonstration_to_json(window_->document()->demonstration()) == open_demo_);
      QVERIFY(!window_->document()->isModified());
    }
    QCOMPARE(tried, 16);
  }

  // A good project naming a bad video or camera opens (the demonstration and the plan are still
  // usable); the error names the bad file and the status bar or the Video step shows it.
  void badMediaInAGoodProjectIsReported() {
    int tried = 0;
    for (const auto& e : entries_) {
      const bool video = e.gui == QLatin1String("video");
      if (!video && e.gui != QLatin1String("camera")) continue;
      ++tried;
      Json j = good_json_;
      j[video ? "video" : "camera"] = e.file.toStdString();
      const QString file = dir_.filePath(QStringLiteral("with_bad_media.demoplan"));
      writeAll(file, QByteArray::fromStdString(j.dump(1)));
      QVERIFY2(window_->openProject(file), qPrintable(window_->lastError()));
      Media* media = window_->document()->media();
      if (video) {
        QVERIFY2(media->video() == nullptr, qPrintable(e.file));
        QVERIFY2(media->videoError().contains(e.file), qPrintable(e.file + QStringLiteral(": ") + media->videoError()));
        QVERIFY2(window_->statusBar()->currentMessage().contains(e.file),
                 qPrintable(window_->statusBar()->currentMessage()));
        QVERIFY(media->camera() != nullptr);
      } else {
        QVERIFY2(media->camera() == nullptr, qPrintable(e.file));
        QVERIFY2(media->cameraError().contains(e.file), qPrintable(e.file + QStringLiteral(": ") + media->cameraError()));
        for (const auto& part : e.expect)
          QVERIFY2(media->cameraError().contains(part), qPrintable(part + QStringLiteral(" not in: ") + media->cameraError()));
        QVERIFY(media->video() != nullptr);
      }
      QVERIFY(demonstration_to_json(window_->document()->demonstration()) == open_demo_);
    }
    QVERIFY(tried >= 9);
    QVERIFY2(window_->openProject(good_), qPrintable(window_->lastError()));
  }

  // Interactively, a refused project is an error dialog naming the file; the open project stays.
  void interactiveRefusalIsAnErrorDialog() {
    MainWindowOptions o;
    o.data_dir = test::dataDir().toStdString();
    o.interactive = true;
    o.restore_layout = false;
    MainWindow w(o);
    QVERIFY2(w.openProject(good_), qPrintable(w.lastError()));
    const QString bad = kCorpus + QStringLiteral("/project/truncated_50.demoplan");
    QString title, text;
    int dialogs = 0;
    QTimer poll;
    poll.setInterval(10);
    connect(&poll, &QTimer::timeout, this, [&] {
      if (auto* box = qobject_cast<QMessageBox*>(QApplication::activeModalWidget())) {
        ++dialogs;
        title = box->windowTitle();
        text = box->text();
        QCOMPARE(box->icon(), QMessageBox::Critical);
        box->close();
      }
    });
    poll.start();
    QVERIFY(!w.openProject(bad));
    poll.stop();
    QCOMPARE(dialogs, 1);
    QVERIFY2(text.contains(bad), qPrintable(text));
    QVERIFY2(title.contains(QStringLiteral("Cannot open")), qPrintable(title));
    QCOMPARE(w.document()->filePath(), QFileInfo(good_).absoluteFilePath());
  }

private:
  std::vector<Entry> entries_;
  QTemporaryDir dir_;
  QString good_, open_path_;
  Json good_json_, open_demo_;
  std::unique_ptr<MainWindow> window_;
};

DEMOPLAN_UI_TEST_MAIN(TestBadCorpusGui)
#include "test_bad_corpus_gui.moc"
