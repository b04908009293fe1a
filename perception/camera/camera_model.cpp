#include "perception/camera/camera_model.h"

#include <algorithm>
#include <cmath>
#include <filesystem>

#include <opencv2/calib3d.hpp>

#include "core/error.h"
#include "core/io/file_extension.h"
#include "perception/camera/calibration_xml.h"
#include "perception/camera/calibration_yaml.h"
#include "perception/io/pose_json.h"
#include "perception/markers/marker_dictionary.h"

namespace demoplan::perception {

namespace {

constexpr const char* kFormat = "demoplan-camera";
constexpr int kVersion = 1;

bool valid_distortion_count(size_t n) { return n == 0 || n == 4 || n == 5 || n == 8 || n == 12 || n == 14; }

void check_intrinsics(const Camera& c, const std::string& path, const std::string& field) {
  if (c.image_size.width <= 0 || c.image_size.height <= 0) throw InputError(path, "image_size", "must be positive");
  if (!(c.fx > 0) || !(c.fy > 0)) throw InputError(path, field, "focal lengths must be > 0");
  if (!std::isfinite(c.fx) || !std::isfinite(c.fy) || !std::isfinite(c.cx) || !std::isfinite(c.cy))
    throw InputError(path, field, "fx, fy, cx and cy must be finite numbers");
}

MarkerBoard board_from_json(const JsonField& b) {
  MarkerBoard board;
  board.dictionary = b["dictionary"].string();
  if (!is_marker_dictionary(board.dictionary)) b["dictionary"].fail("unknown ArUco dictionary '" + board.dictionary + "'");
  board.markers_x = b["markers_x"].integer();
  board.markers_y = b["markers_y"].integer();
  if (board.markers_x < 1 || board.markers_y < 1) b.fail("markers_x and markers_y must be >= 1");
  board.marker_length = b["marker_length"].number();
  board.marker_separation = b["marker_separation"].number();
  if (!(board.marker_length > 0) || board.marker_separation < 0) b.fail("marker_length must be > 0, marker_separation >= 0");
  board.first_id = b.has("first_id") ? b["first_id"].integer() : 0;
  if (board.first_id < 0) b["first_id"].fail("must be >= 0");
  // The board's markers take the ids first_id, first_id + 1, ...: they must exist in the
  // dictionary (OpenCV's GridBoard::create would otherwise be asked for billions of markers).
  const long long ids = static_cast<long long>(board.markers_x) * board.markers_y + board.first_id;
  const int dictionary_size = marker_dictionary(board.dictionary)->bytesList.rows;
  if (ids > dictionary_size)
    b.fail("markers_x x markers_y markers from first_id need ids up to " + std::to_string(ids - 1) + "; " +
           board.dictionary + " has ids 0.." + std::to_string(dictionary_size - 1));
  board.world_T_board = pose_from_json(b["world_T_board"]);
  return board;
}

Camera load_json_camera(const std::string& path) {
  const Json json = read_json_file(path);
  const JsonField root(json, path);
  check_format(root, kFormat, kVersion);
  Camera c;
  const JsonField size = root["image_size"];
  if (size.size() != 2) size.fail("must be [width, height]");
  c.image_size = {size[0].integer(), size[1].integer()};
  const JsonField k = root["intrinsics"];
  c.fx = k["fx"].number();
  c.fy = k["fy"].number();
  c.cx = k["cx"].number();
  c.cy = k["cy"].number();
  check_intrinsics(c, path, "intrinsics");
  if (root.has("distortion")) {
    const JsonField d = root["distortion"];
    for (size_t i = 0; i < d.size(); ++i) c.distortion.push_back(d[i].number());
    if (!valid_distortion_count(c.distortion.size())) d.fail("must hold 0, 4, 5, 8, 12 or 14 coefficients");
  }
  if (root.has("world_T_camera")) c.world_T_camera = pose_from_json(root["world_T_camera"]);
  if (root.has("board")) c.board = board_from_json(root["board"]);
  return c;
}

// What an OpenCV calibration file says, checked as the JSON camera is.
Camera camera_from_calibration(const OpenCvCalibration& cal, const std::string& path) {
  Camera c;
  c.image_size = {cal.image_width, cal.image_height};
  const auto& K = cal.camera_matrix;
  c.fx = K[0];
  c.fy = K[4];
  c.cx = K[2];
  c.cy = K[5];
  check_intrinsics(c, path, "camera_matrix");
  c.distortion = cal.distortion;
  if (!c.distortion.empty() && !valid_distortion_count(c.distortion.size()))
    throw InputError(path, "distortion_coefficients", "must hold 4, 5, 8, 12 or 14 coefficients");
  return c;
}

}  // namespace

cv::Mat Camera::distortion_coefficients() const {
  cv::Mat d(1, static_cast<int>(distortion.size()), CV_64F);
  for (size_t i = 0; i < distortion.size(); ++i) d.at<double>(0, static_cast<int>(i)) = distortion[i];
  return d;
}

cv::Point2d Camera::project(const Eigen::Vector3d& p) const {
  if (distortion.empty()) return {fx * p.x() / p.z() + cx, fy * p.y() / p.z() + cy};
  std::vector<cv::Point3d> in{{p.x(), p.y(), p.z()}};
  std::vector<cv::Point2d> out;
  cv::projectPoints(in, cv::Vec3d(0, 0, 0), cv::Vec3d(0, 0, 0), camera_matrix(), distortion_coefficients(), out);
  return out[0];
}

Camera load_camera(const std::string& path) {
  if (!std::filesystem::is_regular_file(path)) throw InputError(path, "", "camera file not found");
  const std::string ext = lowercase_extension(path);
  if (ext == ".json") return load_json_camera(path);
  // OpenCV calibration files, with our readers: cv::FileStorage's parsers hang or crash on some
  // malformed files (calibration_yaml.h, calibration_xml.h).
  if (ext == ".xml") return camera_from_calibration(read_calibration_xml(path), path);
  // .yaml, .yml, and whatever else: OpenCV's calibration YAML.
  return camera_from_calibration(read_calibration_yaml(path), path);
}

void save_camera(const std::string& path, const Camera& c) {
  Json j{{"format", kFormat},
         {"version", kVersion},
         {"conventions", "OpenCV camera frame (x right, y down, z forward); world_T_camera maps camera to "
                         "world coordinates; poses {t: metres, q: [qx, qy, qz, qw]}"},
         {"image_size", {c.image_size.width, c.image_size.height}},
         {"intrinsics", {{"fx", c.fx}, {"fy", c.fy}, {"cx", c.cx}, {"cy", c.cy}}},
         {"distortion", c.distortion}};
  if (c.world_T_camera) j["world_T_camera"] = pose_to_json(*c.world_T_camera);
  if (c.board) {
    const MarkerBoard& b = *c.board;
    j["board"] = {{"dictionary", b.dictionary},       {"markers_x", b.markers_x},
                  {"markers_y", b.markers_y},         {"marker_length", b.marker_length},
                  {"marker_separation", b.marker_separation}, {"first_id", b.first_id},
                  {"world_T_board", pose_to_json(b.world_T_board)}};
  }
  write_json_file_atomic(path, j);
}

}  // namespace demoplan::perception
