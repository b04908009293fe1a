#pragma once
// Where the tools keep what they compute once and reuse between runs (contour models, fitted
// meshes): a cache folder of the user's, which can be deleted at any time.
#include <mutex>
#include <string>

namespace demoplan {

// $XDG_CACHE_HOME/demoplan/<name>, else ~/.cache/demoplan/<name>; "" without either variable.
std::string user_cache_folder(const std::string& name);

// The folder one cache of the library keeps its files in: "" (nothing kept) until a tool sets
// it at its start, so tests and other programs write nothing; read by any thread.
class CacheFolderSetting {
public:
  void set(const std::string& folder) {
    std::lock_guard lock(mutex_);
    folder_ = folder;
  }
  std::string get() const {
    std::lock_guard lock(mutex_);
    return folder_;
  }

private:
  mutable std::mutex mutex_;
  std::string folder_;
};

}  // namespace demoplan
