#pragma once
// Shared by the UI tests: a main() that isolates settings and autosaves in a temporary folder
// and asks for the OpenGL 3.3 core format the application uses, and small helpers.
#include <QApplication>
#include <QDir>
#include <QElapsedTimer>
#include <QStandardPaths>
#include <QSurfaceFormat>
#include <QTemporaryDir>
#include <QTest>
#include <functional>

namespace demoplan::ui::test {

inline QString dataDir() { return QStringLiteral(DEMOPLAN_DATA_DIR); }
inline QString sampleProject() { return QStringLiteral(DEMOPLAN_SAMPLE_PROJECT); }
inline QString artifactDir() {
  QDir().mkpath(QStringLiteral(DEMOPLAN_ARTIFACT_DIR));
  return QStringLiteral(DEMOPLAN_ARTIFACT_DIR);
}

// True when widgets with a QOpenGLWidget cannot be shown (Qt 6.4's offscreen platform crashes).
inline bool glUnavailable() {
  const QString p = QGuiApplication::platformName();
  return p == QLatin1String("offscreen") || p == QLatin1String("minimal");
}

// Processes events until `done` or the timeout; returns whether `done` became true.
inline bool waitFor(const std::function<bool()>& done, int timeout_ms) {
  QElapsedTimer t;
  t.start();
  while (!done()) {
    if (t.elapsed() > timeout_ms) return false;
    QTest::qWait(5);
  }
  return true;
}

// Measures the longest gap between two runs of the event loop while `run` executes.
class StallMeter : public QObject {
public:
  StallMeter() {
    timer_.setInterval(2);
    connect(&timer_, &QTimer::timeout, this, [this] {
      const qint64 now = clock_.nsecsElapsed();
      if (last_ > 0 && (now - last_) / 1e6 > max_gap_ms_) {
        max_gap_ms_ = (now - last_) / 1e6;
        max_gap_at_ms_ = now / 1e6;
      }
      last_ = now;
    });
  }
  void start() {
    clock_.start();
    last_ = 0;
    max_gap_ms_ = 0;
    timer_.start();
  }
  // When the longest gap ended, in ms since start().
  double maxGapAt() const { return max_gap_at_ms_; }
  double elapsedMs() const { return clock_.nsecsElapsed() / 1e6; }
  double stop() {
    timer_.stop();
    return max_gap_ms_;
  }

private:
  QTimer timer_;
  QElapsedTimer clock_;
  qint64 last_ = 0;
  double max_gap_ms_ = 0;
  double max_gap_at_ms_ = 0;
};

// Runs `body` inside the QApplication every UI test uses: the GL format the 3D view needs and
// the test's own organisation and application names.
template <class Body>
int withTestApplication(int argc, char** argv, Body body) {
  QSurfaceFormat format;
  format.setVersion(3, 3);
  format.setProfile(QSurfaceFormat::CoreProfile);
  format.setDepthBufferSize(24);
  QSurfaceFormat::setDefaultFormat(format);
  QApplication app(argc, argv);
  QApplication::setOrganizationName(QStringLiteral("demoplan-tests"));
  QApplication::setApplicationName(QStringLiteral("demoplan-tests"));
  return body();
}

inline int runTests(int argc, char** argv, QObject* test_object) {
  // Settings, recent files and autosaves of the tests never touch the user's.
  static QTemporaryDir home;
  qputenv("XDG_CONFIG_HOME", (home.path() + QStringLiteral("/config")).toUtf8());
  qputenv("XDG_DATA_HOME", (home.path() + QStringLiteral("/data")).toUtf8());
  qputenv("XDG_RUNTIME_DIR", (home.path() + QStringLiteral("/runtime")).toUtf8());
  QDir().mkpath(home.path() + QStringLiteral("/runtime"));
  QFile::setPermissions(home.path() + QStringLiteral("/runtime"), QFileDevice::ReadOwner | QFileDevice::WriteOwner | QFileDevice::ExeOwner);
  return withTestApplication(argc, argv, [&] { return QTest::qExec(test_object, argc, argv); });
}

}  // namespace demoplan::ui::test

#define DEMOPLAN_UI_TEST_MAIN(TestClass)                    \
  int main(int argc, char** argv) {                         \
    TestClass test;                                         \
    return demoplan::ui::test::runTests(argc, argv, &test); \
  }
