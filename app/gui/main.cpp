// demoplan: the desktop application. Thin: options, the OpenGL format, the main window.
//
//   demoplan [PROJECT_FILE]            open a project (else: recovery, the last project, the sample)
//   demoplan --screenshot out.png ...  render the window, save it, quit (headless checks)
//   demoplan --new shelf_1:panda:1 [--video V] [--camera C] [--markers M] --save-as P.demoplan
//                                      create a project from a benchmark task without a window
#include <QApplication>
#include <QCommandLineParser>
#include <QDir>
#include <QSurfaceFormat>
#include <QTimer>
#include <cstdio>

#include "app/common/data_dir.h"
#include "core/scene/bvh_cache.h"
#include "ui/document/document.h"
#include "ui/mainwindow/main_window.h"

namespace {

int createProject(const QString& spec, const QString& video, const QString& camera, const QString& markers,
                  const QString& out, const std::string& data_dir) {
  const QStringList parts = spec.split(QLatin1Char(':'));
  bool ok = parts.size() == 3;
  const int pose = ok ? parts[2].toInt(&ok) : 0;
  if (!ok) {
    std::fprintf(stderr, "demoplan: --new expects TASK:ROBOT:POSE, e.g. shelf_1:panda:1\n");
    return 2;
  }
  try {
    demoplan::ui::Document doc(data_dir);
    for (const auto& note : doc.newFromBenchmark(parts[0].toStdString(), parts[1].toStdString(), pose))
      std::fprintf(stderr, "demoplan: on the robot's deck: %s\n", note.c_str());
    if (!video.isEmpty()) doc.media()->setVideo(video);
    if (!camera.isEmpty()) doc.media()->setCamera(camera);
    if (!markers.isEmpty()) doc.media()->setMarkers(markers);
    if (!doc.media()->videoError().isEmpty()) throw std::runtime_error(doc.media()->videoError().toStdString());
    if (!doc.media()->cameraError().isEmpty()) throw std::runtime_error(doc.media()->cameraError().toStdString());
    doc.saveAs(out);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "demoplan: %s\n", e.what());
    return 2;
  }
  std::fprintf(stderr, "demoplan: wrote %s\n", qPrintable(out));
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  // A window-less job must not need a display.
  bool headless = false;
  for (int i = 1; i < argc; ++i) headless |= QByteArray(argv[i]) == "--save-as";
  if (headless && qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM")) qputenv("QT_QPA_PLATFORM", "offscreen");

  QSurfaceFormat format;
  format.setRenderableType(QSurfaceFormat::OpenGL);
  format.setVersion(3, 3);
  format.setProfile(QSurfaceFormat::CoreProfile);
  format.setDepthBufferSize(24);
  format.setSamples(4);
  QSurfaceFormat::setDefaultFormat(format);

  QApplication app(argc, argv);
  // Meshes parsed and fitted in earlier runs (mesh_store.h, bvh_cache.h): a scene loads
  // without parsing its mesh files or fitting them.
  demoplan::keep_meshes_between_runs();
  QApplication::setOrganizationName(QStringLiteral("demoplan"));
  QApplication::setApplicationName(QStringLiteral("demoplan"));
  QApplication::setApplicationVersion(QStringLiteral(DEMOPLAN_VERSION));

  QCommandLineParser parser;
  parser.setApplicationDescription(QStringLiteral("Teach a robot cell a pick-and-place task from one video."));
  parser.addHelpOption();
  parser.addVersionOption();
  parser.addPositionalArgument(QStringLiteral("project"), QStringLiteral("project file (.demoplan) to open"), QStringLiteral("[PROJECT_FILE]"));
  QCommandLineOption data_dir({QStringLiteral("data-dir")}, QStringLiteral("benchmark-format data folder (default: the bundled one)"), QStringLiteral("DIR"));
  QCommandLineOption screenshot({QStringLiteral("screenshot")}, QStringLiteral("save a picture of the window to FILE and quit"), QStringLiteral("FILE"));
  QCommandLineOption delay({QStringLiteral("screenshot-delay")}, QStringLiteral("milliseconds to wait before the screenshot (default 1500)"), QStringLiteral("MS"), QStringLiteral("1500"));
  QCommandLineOption sample({QStringLiteral("sample")}, QStringLiteral("open the bundled sample project"));
  QCommandLineOption fresh({QStringLiteral("default-layout")}, QStringLiteral("ignore the saved window layout"));
  QCommandLineOption create({QStringLiteral("new")}, QStringLiteral("create a project from a benchmark task (with --save-as)"), QStringLiteral("TASK:ROBOT:POSE"));
  QCommandLineOption video({QStringLiteral("video")}, QStringLiteral("video of the new project"), QStringLiteral("FILE"));
  QCommandLineOption camera({QStringLiteral("camera")}, QStringLiteral("camera calibration of the new project"), QStringLiteral("FILE"));
  QCommandLineOption markers({QStringLiteral("markers")}, QStringLiteral("marker scene of the new project"), QStringLiteral("FILE"));
  QCommandLineOption save_as({QStringLiteral("save-as")}, QStringLiteral("write the new project to FILE and quit"), QStringLiteral("FILE"));
  QCommandLineOption select({QStringLiteral("select")}, QStringLiteral("select this part, as a click in the 3D view does (its handles drawn)"), QStringLiteral("PART"));
  parser.addOptions({data_dir, screenshot, delay, sample, fresh, create, video, camera, markers, save_as, select});
  parser.process(app);

  const std::string data = parser.isSet(data_dir) ? QDir(parser.value(data_dir)).absolutePath().toStdString()
                                                  : demoplan::app::default_data_dir();
  if (parser.isSet(save_as) || parser.isSet(create)) {
    if (!parser.isSet(save_as) || !parser.isSet(create)) {
      std::fprintf(stderr, "demoplan: --new and --save-as go together\n");
      return 2;
    }
    return createProject(parser.value(create), parser.value(video), parser.value(camera), parser.value(markers),
                         parser.value(save_as), data);
  }

  demoplan::ui::MainWindowOptions options;
  options.data_dir = data;
  options.sample_project = QString::fromStdString(demoplan::app::default_sample_project());
  options.restore_layout = !parser.isSet(fresh) && !parser.isSet(screenshot);
  options.interactive = !parser.isSet(screenshot);
  demoplan::ui::MainWindow window(options);
  window.show();
  const QStringList args = parser.positionalArguments();
  if (parser.isSet(sample)) window.openSample();
  else window.startUp(args.isEmpty() ? QString() : args.front());
  if (parser.isSet(select) && window.document()->hasProject()) {
    const int part = window.document()->scene().object_index(parser.value(select).toStdString());
    if (part < 0) std::fprintf(stderr, "demoplan: --select: no part '%s' in the scene\n", qPrintable(parser.value(select)));
    else window.document()->selectObject(part);
  }

  if (parser.isSet(screenshot)) {
    const QString file = parser.value(screenshot);
    QTimer::singleShot(parser.value(delay).toInt(), &window, [&window, file] {
      const bool ok = window.grab().save(file);
      std::fprintf(stderr, "demoplan: %s %s\n", ok ? "saved" : "could not save", qPrintable(file));
      if (!window.lastError().isEmpty()) std::fprintf(stderr, "demoplan: %s\n", qPrintable(window.lastError()));
      QApplication::exit(ok ? 0 : 1);
    });
  }
  return app.exec();
}
