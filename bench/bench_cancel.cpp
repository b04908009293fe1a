// How long Cancel takes: the time from setting the cancel flag to the worker thread's exit, for
// the plan job (the guided planner on shelf_2, and on tunnel_0/UR5/2 where it also searches
// regrasps) and for the video extraction (a synthetic shelf_1 video, marker tracker). Each job
// is cancelled at several moments of its run; prints the median and the worst latency.
//
//   build/bench/bench_cancel [--repeats N]
#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <functional>
#include <string>
#include <thread>
#include <vector>

#include "core/demo/benchmark_scene.h"
#include "core/planning/plan_job.h"
#include "core/project/benchmark_instance.h"
#include "perception/camera/camera_model.h"
#include "perception/extraction/extract_demonstration.h"
#include "perception/markers/marker_scene.h"
#include "perception/synthetic/synthetic_video.h"
#include "perception/tracking/marker_pose_tracker.h"

using namespace demoplan;
using namespace demoplan::perception;
using Clock = std::chrono::steady_clock;

namespace {

// Runs `job` on a thread, sets the flag after `delay_ms`, returns ms from the flag to the exit
// (negative when the job ended on its own before the flag).
double cancel_latency(const std::function<void(const std::atomic<bool>*)>& job, int delay_ms) {
  std::atomic<bool> cancel{false}, done{false};
  Clock::time_point ended;
  std::thread worker([&] {
    job(&cancel);
    ended = Clock::now();
    done = true;
  });
  std::this_thread::sleep_for(std::chrono::milliseconds(delay_ms));
  const Clock::time_point flagged = Clock::now();
  const bool finished_first = done.load();
  cancel = true;
  worker.join();
  if (finished_first) return -1.0;
  return std::chrono::duration<double, std::milli>(ended - flagged).count();
}

void report(const char* what, std::vector<double> ms, int ended_first) {
  std::sort(ms.begin(), ms.end());
  if (ms.empty()) {
    std::printf("| %s | 0 | - | - | %d |\n", what, ended_first);
    return;
  }
  std::printf("| %s | %zu | %.1f | %.1f | %d |\n", what, ms.size(), ms[ms.size() / 2], ms.back(), ended_first);
}

void plan_case(const char* what, const std::string& task, const std::string& robot, int pose,
               const std::vector<int>& delays, int repeats) {
  const BenchmarkTask t = load_benchmark_task(DEMOPLAN_DATA_DIR, task);
  const BenchmarkInstance in =
      make_benchmark_instance(t, std::make_shared<const Scene>(build_benchmark_scene(t, robot, pose)), PoseSource::Subgoals);
  std::vector<double> ms;
  int first = 0;
  for (int r = 0; r < repeats; ++r)
    for (const int d : delays) {
      PlannerSettings s;
      s.planner.seed = static_cast<std::uint64_t>(r + 1);
      const double l = cancel_latency([&](const std::atomic<bool>* c) { run_plan_job(in.problem, s, {}, c); }, d);
      if (l < 0) ++first;
      else ms.push_back(l);
    }
  report(what, ms, first);
}

}  // namespace

int main(int argc, char** argv) {
  int repeats = 3;
  for (int i = 1; i < argc; ++i)
    if (!std::strcmp(argv[i], "--repeats") && i + 1 < argc) repeats = std::atoi(argv[++i]);
  std::printf("| job | cancels | median ms | max ms | ended before the cancel |\n|---|---|---|---|---|\n");
  plan_case("plan shelf_2 Panda pose 0", "shelf_2", "panda", 0, {20, 100, 300, 700}, repeats);
  // From 10,000 iterations on (about 1.5-2 s) it also searches regrasp placements.
  plan_case("plan tunnel_0 UR5 pose 2 (regrasps)", "tunnel_0", "ur5", 2, {500, 2000, 3000, 4500}, repeats);

  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "demoplan_bench_cancel";
  SynthOptions so;
  so.data_dir = DEMOPLAN_DATA_DIR;
  so.task = "shelf_1";
  const SynthOutput v = write_synthetic_demonstration(so, dir.string());
  const MarkerScene scene = load_marker_scene(v.scene);
  const Camera camera = load_camera(v.camera);
  std::vector<double> ms;
  int first = 0;
  for (int r = 0; r < repeats; ++r)
    for (const int d : {50, 300, 1000, 2000}) {
      const double l = cancel_latency(
          [&](const std::atomic<bool>* c) {
            MarkerPoseTracker tracker(scene);
            ExtractionOptions eo;
            eo.cancel = c;
            extract_demonstration(v.video, camera, tracker, scene.task, eo);
          },
          d + 37 * r);
      if (l < 0) ++first;
      else ms.push_back(l);
    }
  report("extract shelf_1 synthetic video (markers)", ms, first);
  std::filesystem::remove_all(dir);
  return 0;
}
