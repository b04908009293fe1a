#include "core/model/concurrent_urdfs.h"

#include <algorithm>

#include "core/parallel_for.h"

namespace demoplan {

ConcurrentUrdfs::ConcurrentUrdfs(std::vector<std::string> files, UrdfOptions options)
    : files_(std::move(files)), options_(std::move(options)), promises_(files_.size()) {
  for (auto& p : promises_) models_.push_back(p.get_future());
  reader_ = std::thread([this] {
    parallel_for(
        files_.size(), static_cast<int>(std::max(1u, std::thread::hardware_concurrency())),
        [this](size_t i) {
          try {
            promises_[i].set_value(load_urdf(files_[i], options_));
          } catch (...) {
            promises_[i].set_exception(std::current_exception());
          }
        },
        {}, &stop_);
  });
}

ConcurrentUrdfs::~ConcurrentUrdfs() {
  stop_ = true;
  reader_.join();
}

RobotModel ConcurrentUrdfs::take(size_t i) { return models_.at(i).get(); }

}  // namespace demoplan
