#include "perception/markers/marker_dictionary.h"

#include <stdexcept>
#include <utility>

namespace demoplan::perception {

namespace {
const std::vector<std::pair<std::string, cv::aruco::PREDEFINED_DICTIONARY_NAME>>& table() {
  static const std::vector<std::pair<std::string, cv::aruco::PREDEFINED_DICTIONARY_NAME>> t{
      {"DICT_4X4_50", cv::aruco::DICT_4X4_50},     {"DICT_4X4_100", cv::aruco::DICT_4X4_100},
      {"DICT_4X4_250", cv::aruco::DICT_4X4_250},   {"DICT_5X5_100", cv::aruco::DICT_5X5_100},
      {"DICT_5X5_250", cv::aruco::DICT_5X5_250},   {"DICT_6X6_250", cv::aruco::DICT_6X6_250},
      {"DICT_ARUCO_ORIGINAL", cv::aruco::DICT_ARUCO_ORIGINAL}};
  return t;
}
}  // namespace

cv::Ptr<cv::aruco::Dictionary> marker_dictionary(const std::string& name) {
  for (const auto& [n, id] : table())
    if (n == name) return cv::aruco::getPredefinedDictionary(id);
  throw std::invalid_argument("unknown ArUco dictionary '" + name + "'");
}

bool is_marker_dictionary(const std::string& name) {
  for (const auto& [n, id] : table())
    if (n == name) return true;
  return false;
}

std::vector<std::string> marker_dictionary_names() {
  std::vector<std::string> names;
  for (const auto& [n, id] : table()) names.push_back(n);
  return names;
}

}  // namespace demoplan::perception
