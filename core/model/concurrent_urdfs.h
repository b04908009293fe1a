#pragma once
// URDF files read concurrently: a scene's URDFs and their meshes are most of its loading time,
// and the robot's, the furniture's and every part's are independent. Each model is taken where it
// is used, so a scene meets the files' errors in the order reading them one by one would.
#include <atomic>
#include <future>
#include <string>
#include <thread>
#include <vector>

#include "core/model/robot_model.h"

namespace demoplan {

class ConcurrentUrdfs {
public:
  // Starts reading the files, on up to hardware_concurrency() threads, in the order given.
  ConcurrentUrdfs(std::vector<std::string> files, UrdfOptions options);
  // Files not yet started are skipped; waits for those being read.
  ~ConcurrentUrdfs();
  ConcurrentUrdfs(const ConcurrentUrdfs&) = delete;
  ConcurrentUrdfs& operator=(const ConcurrentUrdfs&) = delete;

  // The model of files[i], once read (each taken once); raises that file's error.
  RobotModel take(size_t i);

private:
  std::vector<std::string> files_;
  UrdfOptions options_;
  std::vector<std::promise<RobotModel>> promises_;
  std::vector<std::future<RobotModel>> models_;
  std::atomic<bool> stop_{false};
  std::thread reader_;
};

}  // namespace demoplan
