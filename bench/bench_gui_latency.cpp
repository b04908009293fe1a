// How long the GUI thread can go without answering while the planner runs: the real main
// window (3D view growing the trees, planner panel, step bar) plans a benchmark task while a
// 1 ms timer on the GUI thread records the gaps between its ticks. A gap is time in which a
// click or a repaint would have waited. Needs an X server for the 3D view: run under xvfb-run.
//
//   xvfb-run -a -s '-screen 0 1280x800x24' build/bench/bench_gui_latency
//       [--task shelf_2] [--robot panda] [--pose 4] [--seeds 1-5] [--hide-3d]
//
// --hide-3d hides the 3D view: what is left is the GUI thread's own work, without the cost of
// composing an OpenGL widget into the window (large on a software renderer such as llvmpipe).
#include <QApplication>
#include <QElapsedTimer>
#include <QEventLoop>
#include <QSurfaceFormat>
#include <QTimer>
#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

#include "ui/document/document.h"
#include "ui/mainwindow/main_window.h"
#include "ui/view3d/scene_view.h"

using namespace demoplan;
using namespace demoplan::ui;

namespace {

struct Run {
  int seed = 0;
  bool solved = false;
  double planning_s = 0.0;
  int snapshots = 0;
  std::vector<double> gaps_ms;
  double max_paint_ms = 0.0;  // the 3D view's longest frame, GL included
  double worst_at_ms = 0.0;   // when the longest gap ended, from the start of the job
  double start_call_ms = 0.0;  // Plan pressed: the synchronous part (job set up, 'started' handlers)
  double press_ms = 0.0;       // the first gap: the press of Plan and its repaint
};

double percentile(std::vector<double> v, double p) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  return v[std::min(v.size() - 1, static_cast<size_t>(p * static_cast<double>(v.size() - 1) + 0.5))];
}

std::string arg(int argc, char** argv, const std::string& name, const std::string& fallback) {
  for (int i = 1; i + 1 < argc; ++i)
    if (argv[i] == name) return argv[i + 1];
  return fallback;
}

}  // namespace

int main(int argc, char** argv) {
  QSurfaceFormat format;
  format.setRenderableType(QSurfaceFormat::OpenGL);
  format.setVersion(3, 3);
  format.setProfile(QSurfaceFormat::CoreProfile);
  format.setDepthBufferSize(24);
  QSurfaceFormat::setDefaultFormat(format);
  QApplication app(argc, argv);
  const std::string task = arg(argc, argv, "--task", "shelf_2"), robot = arg(argc, argv, "--robot", "panda");
  const int pose = std::stoi(arg(argc, argv, "--pose", "4"));
  const std::string seeds = arg(argc, argv, "--seeds", "1-5");
  const int first = std::stoi(seeds.substr(0, seeds.find('-')));
  const int last = seeds.find('-') == std::string::npos ? first : std::stoi(seeds.substr(seeds.find('-') + 1));

  MainWindowOptions o;
  o.data_dir = DEMOPLAN_DATA_DIR;
  o.interactive = false;
  o.restore_layout = false;
  MainWindow window(o);
  window.resize(1280, 800);
  window.show();
  for (int i = 1; i < argc; ++i)
    if (std::string(argv[i]) == "--hide-3d") window.sceneView()->hide();
  Document* doc = window.document();
  doc->newFromBenchmark(task, robot, pose);
  QEventLoop settle;
  QTimer::singleShot(500, &settle, &QEventLoop::quit);  // first paint, GL set up
  settle.exec();

  std::vector<Run> runs;
  std::vector<double> all_gaps, all_press;
  for (int seed = first; seed <= last; ++seed) {
    PlannerSettings s = doc->planning()->settings();
    s.planner.seed = static_cast<std::uint64_t>(seed);
    doc->planning()->setSettings(s);
    Run run;
    run.seed = seed;
    QElapsedTimer clock;
    QTimer tick;
    tick.setTimerType(Qt::PreciseTimer);
    tick.setInterval(1);
    qint64 last_tick = 0;
    QObject::connect(&tick, &QTimer::timeout, [&] {
      const qint64 now = clock.nsecsElapsed();
      run.gaps_ms.push_back(static_cast<double>(now - last_tick) / 1e6);
      if (run.gaps_ms.back() >= *std::max_element(run.gaps_ms.begin(), run.gaps_ms.end()))
        run.worst_at_ms = static_cast<double>(now) / 1e6;
      last_tick = now;
    });
    QObject::connect(doc->planning()->runner(), &PlanRunner::progress, &tick, [&] {
      ++run.snapshots;
      run.max_paint_ms = std::max(run.max_paint_ms, window.sceneView()->lastPaintMs());
    });
    QEventLoop done;
    QObject::connect(doc->planning()->runner(), &PlanRunner::finished, &done, &QEventLoop::quit);
    clock.start();
    tick.start();
    QElapsedTimer start_call;
    start_call.start();
    const bool started = doc->planning()->start();
    run.start_call_ms = static_cast<double>(start_call.nsecsElapsed()) / 1e6;
    if (!started) {
      std::fprintf(stderr, "bench_gui_latency: planning did not start\n");
      return 1;
    }
    done.exec();
    tick.stop();
    const PlanResultData* r = doc->planning()->result();
    run.solved = r && r->summary.solved;
    run.planning_s = r ? r->summary.planning_time_s : 0.0;
    // The first gap holds the press of Plan itself (the planner dock raised, the panels reset);
    // the others are the planning proper.
    if (!run.gaps_ms.empty()) run.press_ms = run.gaps_ms.front();
    std::vector<double> planning(run.gaps_ms.begin() + (run.gaps_ms.empty() ? 0 : 1), run.gaps_ms.end());
    all_gaps.insert(all_gaps.end(), planning.begin(), planning.end());
    all_press.push_back(run.press_ms);
    std::printf("%s %s pose %d seed %d: %s in %.2f s, %d snapshots; GUI thread gaps: max %.1f ms, p99 %.1f ms, "
                "median %.2f ms over %zu ticks (the longest ending %.0f ms in); Plan itself %.1f ms; longest 3D frame %.1f ms\n",
                task.c_str(), robot.c_str(), pose, seed, run.solved ? "solved" : "not solved", run.planning_s,
                run.snapshots, percentile(run.gaps_ms, 1.0), percentile(run.gaps_ms, 0.99),
                percentile(run.gaps_ms, 0.5), run.gaps_ms.size(), run.worst_at_ms, run.start_call_ms, run.max_paint_ms);
    runs.push_back(std::move(run));
  }
  std::printf("all runs, while planning (after the press of Plan): longest GUI-thread stall %.1f ms, p99 %.1f ms, "
              "p999 %.1f ms over %zu ticks; the press of Plan itself: longest %.1f ms\n",
              percentile(all_gaps, 1.0), percentile(all_gaps, 0.99), percentile(all_gaps, 0.999), all_gaps.size(),
              percentile(all_press, 1.0));
  return 0;
}
