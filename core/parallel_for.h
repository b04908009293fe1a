#pragma once
// Independent jobs over indices on a few threads, as `bench` runs its runs and the placement
// search its candidates: work(i) for every i in [0, count), each once, started in increasing
// order on `jobs` threads (the calling thread one of them); done(i), when given, runs after
// work(i) one call at a time, for progress lines and results shared between threads. Once
// `cancel` is set, no further index is started.
#include <algorithm>
#include <atomic>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace demoplan {

inline void parallel_for(size_t count, int jobs, const std::function<void(size_t)>& work,
                         const std::function<void(size_t)>& done = {}, const std::atomic<bool>* cancel = nullptr) {
  std::mutex mutex;
  size_t next = 0;
  auto worker = [&] {
    while (true) {
      size_t i;
      {
        std::lock_guard lock(mutex);
        if (next >= count || (cancel && cancel->load())) return;
        i = next++;
      }
      work(i);
      if (done) {
        std::lock_guard lock(mutex);
        done(i);
      }
    }
  };
  const int threads = std::clamp(jobs, 1, static_cast<int>(std::max<size_t>(count, 1)));
  std::vector<std::thread> pool;
  for (int t = 1; t < threads; ++t) pool.emplace_back(worker);
  worker();
  for (auto& t : pool) t.join();
}

}  // namespace demoplan
