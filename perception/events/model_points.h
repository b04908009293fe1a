#pragma once
// Points of the parts' models (their collision meshes, in the part frame, metres), for the
// BOP MSSD of an evaluation.
#include <map>
#include <string>
#include <vector>

#include <Eigen/Core>

namespace demoplan::perception {

// Of every object of benchmark task `task` in `data_dir`, at most `max_points` each; empty when
// the data folder has no such task.
std::map<std::string, std::vector<Eigen::Vector3d>> benchmark_model_points(const std::string& data_dir,
                                                                            const std::string& task,
                                                                            size_t max_points = 3000);

}  // namespace demoplan::perception
