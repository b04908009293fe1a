#include "core/placement/placement_search.h"

#include <algorithm>
#include <mutex>
#include <thread>

namespace demoplan {

std::vector<PlacementCandidate> run_placement_search(const ProblemAtBase& problem_at,
                                                     const std::vector<BasePose>& candidates,
                                                     const std::vector<int>& indices,
                                                     const PlacementSettings& settings, int jobs,
                                                     const CandidateDone& on_done, const std::atomic<bool>* cancel) {
  std::vector<PlacementCandidate> out(indices.size());
  for (size_t k = 0; k < indices.size(); ++k) {
    out[k].index = indices[k];
    out[k].base = candidates.at(static_cast<size_t>(indices[k]));
  }
  std::mutex mutex;
  size_t next = 0, done = 0;
  auto worker = [&] {
    while (true) {
      size_t k;
      {
        std::lock_guard lock(mutex);
        if (next >= indices.size() || (cancel && cancel->load())) return;
        k = next++;
      }
      PlacementCandidate c = evaluate_candidate(problem_at, out[k].index, out[k].base, settings, cancel);
      std::lock_guard lock(mutex);
      out[k] = std::move(c);
      ++done;
      if (on_done) on_done(out[k], done, indices.size());
    }
  };
  const int threads = std::clamp(jobs, 1, static_cast<int>(std::max<size_t>(indices.size(), 1)));
  std::vector<std::thread> pool;
  for (int t = 1; t < threads; ++t) pool.emplace_back(worker);
  worker();
  for (auto& t : pool) t.join();
  return out;
}

}  // namespace demoplan
