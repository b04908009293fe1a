#pragma once
// ArUco dictionaries by name ("DICT_4X4_100", ...), as they are written in scene and camera files.
#include <string>
#include <vector>

#include <opencv2/aruco.hpp>

namespace demoplan::perception {

// Throws std::invalid_argument for an unknown name.
cv::Ptr<cv::aruco::Dictionary> marker_dictionary(const std::string& name);
bool is_marker_dictionary(const std::string& name);
std::vector<std::string> marker_dictionary_names();

}  // namespace demoplan::perception
