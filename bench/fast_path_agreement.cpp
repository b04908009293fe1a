// The collision checker's fast path against FCL alone, at scale (issue 19): a million states per
// benchmark scene (tasks shelf_0..2, tunnel_0, waiter_0; every robot with a pose 0; states as
// tests/core/fast_path_agreement.h draws them), and every sample the validator checks on a
// path the guided planner finds in each scene (plus the paths given as arguments, e.g. the CLI's
// plan output). Prints the counts; exits 1 on any disagreement.
//   fast_path_agreement [--states N] [--plan-seconds S] [--threads T] [path.json ...]
#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "core/path/path_interpolation.h"
#include "tests/core/fast_path_agreement.h"
#include "tests/core/planning_problem.h"

using namespace demoplan;

namespace {

struct Job {
  std::string task, robot;
};

// Every state the validator would check on `path`, compared.
// (The planner leaves Path::task and robot to its caller: they are passed.)
void compare_path(const Path& path, const std::string& task, const std::string& robot, int pose, AgreementCounts& c) {
  FastPathAgreement agreement(DEMOPLAN_DATA_DIR, task, robot, pose);
  const PathInterpolator interp(agreement.scene(), path);
  for (double t : interp.sample_parameters(0.001, 0.01)) agreement.compare(interp.at(t), {}, c);
}

void print(const char* what, const std::string& name, const AgreementCounts& c, double seconds) {
  std::printf("%-8s %-22s states %9ld  colliding %8ld  held %8ld  near boundary %8ld  disagreements %ld  "
              "pair mismatches %ld  answer-only disagreements %ld  (%.0f s)\n",
              what, name.c_str(), c.states, c.colliding, c.held, c.boundary, c.disagreements, c.pair_mismatches,
              c.answer_only_disagreements, seconds);
  if (!c.first_disagreement.empty()) std::printf("  first: %s\n", c.first_disagreement.c_str());
  std::fflush(stdout);
}

}  // namespace

int main(int argc, char** argv) {
  long states = 1'000'000;
  double plan_seconds = 30.0;
  int threads = 2;
  std::vector<std::string> path_files;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--states" && i + 1 < argc) states = std::atol(argv[++i]);
    else if (a == "--plan-seconds" && i + 1 < argc) plan_seconds = std::atof(argv[++i]);
    else if (a == "--threads" && i + 1 < argc) threads = std::max(1, std::atoi(argv[++i]));
    else path_files.push_back(a);
  }

  std::vector<Job> jobs;
  for (const std::string task : {"shelf_0", "shelf_1", "shelf_2", "tunnel_0", "waiter_0"}) {
    const BenchmarkTask t = load_benchmark_task(DEMOPLAN_DATA_DIR, task);
    for (const std::string robot : {"panda", "ur5", "kmr_iiwa"}) {
      const auto poses = benchmark_pose_ids(t, robot);
      if (std::find(poses.begin(), poses.end(), 0) != poses.end()) jobs.push_back({task, robot});
    }
  }

  std::mutex mutex;
  AgreementCounts random_total, path_total;
  int planned = 0, not_solved = 0;
  std::atomic<size_t> next{0};
  auto worker = [&] {
    for (size_t j; (j = next++) < jobs.size();) {
      const Job& job = jobs[j];
      const std::string name = job.task + " " + job.robot;
      auto t0 = std::chrono::steady_clock::now();
      FastPathAgreement agreement(DEMOPLAN_DATA_DIR, job.task, job.robot, 0);
      const AgreementCounts c = agreement.run(states, 1000 + j);
      const double random_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();

      t0 = std::chrono::steady_clock::now();
      AgreementCounts p;
      bool solved = false;
      if (plan_seconds > 0) {
        const BenchmarkProblem problem(job.task, job.robot, 0);
        PlannerParams params;
        params.time_limit = plan_seconds;
        params.seed = 1;
        const PlanResult result = problem.plan(params);
        solved = result.solved;
        if (solved) compare_path(result.path, job.task, job.robot, 0, p);
      }
      const double path_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();

      std::lock_guard lock(mutex);
      print("random", name, c, random_s);
      if (plan_seconds > 0) {
        if (solved) print("path", name, p, path_s);
        else std::printf("path     %-22s not solved in %.0f s\n", name.c_str(), plan_seconds);
      }
      random_total.add(c);
      path_total.add(p);
      (solved ? planned : not_solved) += plan_seconds > 0;
    }
  };
  std::vector<std::thread> pool;
  for (int t = 0; t < threads; ++t) pool.emplace_back(worker);
  for (auto& t : pool) t.join();

  for (const auto& file : path_files) {
    const Path path = load_path(file);
    AgreementCounts p;
    compare_path(path, path.task, path.robot, path.robot_pose, p);
    print("path", file, p, 0.0);
    path_total.add(p);
  }

  std::printf("\n%zu scenes: %ld random/held/moved/boundary states, %ld disagreements, %ld pair mismatches, "
              "%ld answer-only disagreements\n",
              jobs.size(), random_total.states, random_total.disagreements, random_total.pair_mismatches,
              random_total.answer_only_disagreements);
  std::printf("%d planned paths (%d not solved) and %zu given: %ld path states, %ld disagreements, %ld answer-only\n",
              planned, not_solved, path_files.size(), path_total.states, path_total.disagreements,
              path_total.answer_only_disagreements);
  return random_total.disagreements + path_total.disagreements + random_total.pair_mismatches +
                     random_total.answer_only_disagreements + path_total.answer_only_disagreements > 0
             ? 1
             : 0;
}
