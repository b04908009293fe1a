#pragma once
// What the CLI's figures need of Qt: fonts, hence a QGuiApplication. The CLI never opens a
// window, so the offscreen platform works everywhere; Qt's remarks (no XDG_RUNTIME_DIR, ...)
// are not ours to print: stderr is the summary.
#include <QGuiApplication>
#include <iostream>
#include <memory>

namespace demoplan::cli {

class OffscreenGui {
public:
  OffscreenGui() {
    if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM")) qputenv("QT_QPA_PLATFORM", "offscreen");
    previous_ = qInstallMessageHandler([](QtMsgType type, const QMessageLogContext&, const QString& m) {
      if (type == QtCriticalMsg || type == QtFatalMsg) std::cerr << m.toStdString() << "\n";
    });
    if (!QGuiApplication::instance()) app_ = std::make_unique<QGuiApplication>(argc_, argv_);
  }
  ~OffscreenGui() {
    app_.reset();
    qInstallMessageHandler(previous_);
  }
  OffscreenGui(const OffscreenGui&) = delete;
  OffscreenGui& operator=(const OffscreenGui&) = delete;

private:
  static inline int argc_ = 1;
  static inline char arg0_[] = "demoplan-cli";
  static inline char* argv_[] = {arg0_, nullptr};
  QtMessageHandler previous_ = nullptr;
  std::unique_ptr<QGuiApplication> app_;
};

}  // namespace demoplan::cli
