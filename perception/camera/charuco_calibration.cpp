#include "perception/camera/charuco_calibration.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <filesystem>
#include <map>
#include <optional>
#include <stdexcept>

#include <opencv2/calib3d.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "core/error.h"
#include "core/io/file_extension.h"
#include "core/statistics.h"
#include "perception/markers/marker_detector.h"
#include "perception/video/video_reader.h"

namespace demoplan::perception {

namespace fs = std::filesystem;

namespace {

std::string size_text(cv::Size s) { return std::to_string(s.width) + "x" + std::to_string(s.height); }

// The frames of a video, or the images of a folder sorted by name, by index.
class FrameSource {
public:
  explicit FrameSource(const std::string& path) : path_(path) {
    if (fs::is_directory(path)) {
      for (const auto& e : fs::directory_iterator(path)) {
        const std::string ext = lowercase_extension(e.path());
        if (e.is_regular_file() && (ext == ".png" || ext == ".jpg" || ext == ".jpeg" || ext == ".bmp" ||
                                    ext == ".tif" || ext == ".tiff"))
          images_.push_back(e.path());
      }
      std::sort(images_.begin(), images_.end());
      if (images_.empty()) throw InputError(path, "", "no images (png, jpg, bmp, tif) in the folder");
      size_ = frame(0).size();
    } else {
      video_.emplace(path, 2);
      size_ = video_->size();
    }
  }

  int count() const { return video_ ? video_->frame_count() : int(images_.size()); }
  cv::Size size() const { return size_; }
  std::string image_name(int i) const { return video_ ? std::string() : images_[size_t(i)].filename().string(); }

  // BGR or grey, 8 bit.
  cv::Mat frame(int i) {
    if (video_) return video_->frame(i);
    const std::string file = images_[size_t(i)].string();
    cv::Mat image;
    try {
      image = cv::imread(file, cv::IMREAD_COLOR);
    } catch (const cv::Exception&) {
      image.release();
    }
    if (image.empty()) throw InputError(file, "", "cannot be read as an image");
    if (!size_.empty() && image.size() != size_)
      throw InputError(file, "", "is " + size_text(image.size()) + " but the first image is " + size_text(size_) +
                                     ": all views must come from the same camera mode");
    return image;
  }

private:
  std::string path_;
  std::optional<VideoReader> video_;
  std::vector<fs::path> images_;
  cv::Size size_;
};

// What one candidate view shows of the board.
struct Detection {
  std::vector<cv::Point2f> corners;
  std::vector<int> ids;
};

// Sharpness of the board's region (see the header): the energy of the second derivative in the
// direction where it is smallest (a motion blur smooths the edges across its direction only, and
// the Laplacian would still see the others), over the hull of the corners, per intensity
// variance, times the side of a square in pixels.
double sharpness(const cv::Mat& grey, const Detection& d, const CharucoBoard& board) {
  std::vector<cv::Point2f> hull;
  cv::convexHull(d.corners, hull);
  std::vector<cv::Point2f> on_board;
  const int per_row = board.squares_x - 1;
  for (int id : d.ids) on_board.emplace_back(float(id % per_row), float(id / per_row));
  std::vector<cv::Point2f> board_hull;
  cv::convexHull(on_board, board_hull);
  const double squares = cv::contourArea(board_hull), area = cv::contourArea(hull);
  if (squares < 1 || area < 1) return 0.0;
  cv::Mat mask = cv::Mat::zeros(grey.size(), CV_8U);
  std::vector<cv::Point> poly;
  for (const auto& p : hull) poly.emplace_back(int(std::lround(p.x)), int(std::lround(p.y)));
  cv::fillConvexPoly(mask, poly, cv::Scalar(255));
  const cv::Rect box = cv::boundingRect(poly) & cv::Rect(0, 0, grey.cols, grey.rows);
  if (box.area() == 0) return 0.0;
  const cv::Mat g = grey(box), m = mask(box);
  cv::Mat xx, yy, xy;
  cv::Sobel(g, xx, CV_32F, 2, 0);
  cv::Sobel(g, yy, CV_32F, 0, 2);
  cv::Sobel(g, xy, CV_32F, 1, 1);
  // d_uu = c^2 xx + 2 c s xy + s^2 yy along u = (c, s); its mean square from six products.
  auto mean_of = [&](const cv::Mat& a, const cv::Mat& b) { return cv::mean(a.mul(b), m)[0]; };
  const double A = mean_of(xx, xx), B = mean_of(yy, yy), C = mean_of(xy, xy), D = mean_of(xx, yy),
               F = mean_of(xx, xy), G = mean_of(yy, xy);
  double least = std::numeric_limits<double>::max();
  for (int k = 0; k < 36; ++k) {
    const double c = std::cos(k * M_PI / 36), s = std::sin(k * M_PI / 36);
    least = std::min(least, c * c * c * c * A + s * s * s * s * B + 4 * c * c * s * s * C + 2 * c * c * s * s * D +
                                4 * c * c * c * s * F + 4 * c * s * s * s * G);
  }
  cv::Scalar mean, dev;
  cv::meanStdDev(g, mean, dev, m);
  if (dev[0] < 1e-6) return 0.0;
  const double square_px = std::sqrt(area / squares);
  return least / (dev[0] * dev[0]) * square_px;
}

// Mean motion of the corners two views share, or -1 when they share less than half of either's.
double shared_corner_motion(const Detection& a, const Detection& b) {
  std::map<int, cv::Point2f> at;
  for (size_t k = 0; k < a.ids.size(); ++k) at[a.ids[k]] = a.corners[k];
  double sum = 0;
  size_t shared = 0;
  for (size_t k = 0; k < b.ids.size(); ++k)
    if (auto it = at.find(b.ids[k]); it != at.end()) {
      sum += cv::norm(it->second - b.corners[k]);
      ++shared;
    }
  if (2 * shared < a.ids.size() || 2 * shared < b.ids.size() || shared == 0) return -1;
  return sum / double(shared);
}

struct Calibrated {
  cv::Mat camera_matrix, distortion;
  double rms = 0;
  std::vector<double> per_view;
};

Calibrated calibrate(const std::vector<const Detection*>& views, const cv::Ptr<cv::aruco::CharucoBoard>& board,
                     cv::Size size) {
  std::vector<std::vector<cv::Point2f>> corners;
  std::vector<std::vector<int>> ids;
  for (const Detection* d : views) {
    corners.push_back(d->corners);
    ids.push_back(d->ids);
  }
  Calibrated c;
  cv::Mat rvecs, tvecs, std_in, std_ex, per_view;
  try {
    c.rms = cv::aruco::calibrateCameraCharuco(corners, ids, board, size, c.camera_matrix, c.distortion, rvecs, tvecs,
                                              std_in, std_ex, per_view);
  } catch (const cv::Exception& e) {
    throw std::runtime_error("the calibration failed: " + e.err);
  }
  for (int k = 0; k < per_view.rows * per_view.cols; ++k) c.per_view.push_back(per_view.at<double>(k));
  if (!std::isfinite(c.rms)) throw std::runtime_error("the calibration failed: its error is not finite");
  return c;
}

}  // namespace

CharucoCalibration calibrate_charuco(const std::string& source_path, const CharucoBoard& board,
                                     const CharucoCalibrationOptions& o) {
  const auto t0 = std::chrono::steady_clock::now();
  FrameSource source(source_path);
  CharucoCalibration r;
  r.frames = source.count();
  const cv::Size size = source.size();
  const auto cv_board = board.make();
  const MarkerDetector detector(board.dictionary);

  // The candidates, spread evenly over the source.
  const int n = r.frames, k = std::min(n, std::max(1, o.max_views));
  std::vector<Detection> detections(static_cast<size_t>(k));
  for (int i = 0; i < k; ++i) {
    if (o.cancel && o.cancel->load()) {
      r.cancelled = true;
      break;
    }
    CalibrationView v;
    v.frame = int((i + 0.5) * n / k);
    v.image = source.image_name(v.frame);
    const cv::Mat image = source.frame(v.frame);
    cv::Mat grey;
    if (image.channels() == 1) grey = image;
    else cv::cvtColor(image, grey, cv::COLOR_BGR2GRAY);
    std::vector<std::vector<cv::Point2f>> marker_corners;
    std::vector<int> marker_ids;
    for (const MarkerDetection& m : detector.detect(grey))
      if (m.id >= board.first_id && m.id < board.first_id + board.marker_count()) {
        marker_corners.emplace_back(m.corners.begin(), m.corners.end());
        marker_ids.push_back(m.id);
      }
    Detection& d = detections[size_t(i)];
    if (!marker_ids.empty())
      cv::aruco::interpolateCornersCharuco(marker_corners, marker_ids, grey, cv_board, d.corners, d.ids);
    v.corners = int(d.ids.size());
    if (v.corners < std::max(4, o.min_corners))
      v.rejected = v.corners == 0 ? "board not seen" : "too few corners (" + std::to_string(v.corners) + ")";
    else if (cv::aruco::testCharucoCornersCollinear(cv_board, d.ids))
      v.rejected = "corners on one line";
    else
      v.sharpness = sharpness(grey, d, board);
    r.views.push_back(v);
    if (o.progress) o.progress(i + 1, k);
  }
  const auto finish = [&] {
    r.views_used = 0;
    for (const auto& v : r.views) r.views_used += v.used ? 1 : 0;
    r.views_rejected = int(r.views.size()) - r.views_used;
    r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  };
  if (r.cancelled) {
    finish();
    return r;
  }

  // Blurred: relative to the median of the views that show the board.
  std::vector<double> sharp;
  for (const auto& v : r.views)
    if (v.rejected.empty()) sharp.push_back(v.sharpness);
  if (sharp.empty())
    throw InputError(source_path, "",
                     "no frame showed the board (" + std::to_string(board.squares_x) + " x " +
                         std::to_string(board.squares_y) + " ChArUco, " + board.dictionary + ", ids " +
                         std::to_string(board.first_id) + "-" + std::to_string(board.first_id + board.marker_count() - 1) +
                         "; " + std::to_string(r.views.size()) + " of " + std::to_string(n) + " frames looked at)");
  const double median_sharpness = order_statistic(sharp, sharp.size() / 2);
  for (auto& v : r.views)
    if (v.rejected.empty() && v.sharpness < o.blur_ratio * median_sharpness) v.rejected = "blurred";

  // Duplicates: the sharpest view of a group is kept.
  std::vector<size_t> order;
  for (size_t i = 0; i < r.views.size(); ++i)
    if (r.views[i].rejected.empty()) order.push_back(i);
  std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) { return r.views[a].sharpness > r.views[b].sharpness; });
  const double duplicate_px = o.duplicate_px * std::hypot(size.width, size.height);
  std::vector<size_t> kept;
  for (size_t i : order) {
    for (size_t j : kept) {
      const double motion = shared_corner_motion(detections[i], detections[j]);
      if (motion >= 0 && motion < duplicate_px) {
        r.views[i].rejected = "duplicate of frame " + std::to_string(r.views[j].frame);
        break;
      }
    }
    if (r.views[i].rejected.empty()) kept.push_back(i);
  }
  std::sort(kept.begin(), kept.end());

  auto too_few = [&](const std::vector<size_t>& used) {
    std::map<std::string, int> reasons;
    for (const auto& v : r.views)
      if (!v.rejected.empty()) ++reasons[v.rejected.rfind("duplicate", 0) == 0 ? "duplicate" : v.rejected];
    std::string why;
    for (const auto& [reason, count] : reasons) why += (why.empty() ? "" : ", ") + std::to_string(count) + " " + reason;
    throw InputError(source_path, "",
                     "only " + std::to_string(used.size()) + " usable views of " + std::to_string(r.views.size()) +
                         " looked at (at least " + std::to_string(o.min_views) + " needed; rejected: " + why +
                         "): show the board in more, different poses");
  };
  if (int(kept.size()) < std::max(3, o.min_views)) too_few(kept);

  auto run = [&](const std::vector<size_t>& used) {
    std::vector<const Detection*> views;
    for (size_t i : used) views.push_back(&detections[i]);
    return calibrate(views, cv_board, size);
  };
  Calibrated c = run(kept);
  // Outliers (a misread corner, a rolling-shutter smear): dropped once, then calibrated again.
  const double limit = std::max(o.min_outlier_px, o.outlier_ratio * order_statistic(c.per_view, c.per_view.size() / 2));
  std::vector<size_t> inliers;
  for (size_t m = 0; m < kept.size(); ++m)
    if (c.per_view[m] <= limit) inliers.push_back(kept[m]);
  if (inliers.size() < kept.size() && int(inliers.size()) >= std::max(3, o.min_views)) {
    for (size_t m = 0; m < kept.size(); ++m)
      if (c.per_view[m] > limit) {
        char text[64];
        std::snprintf(text, sizeof text, "reprojection error %.2f px", c.per_view[m]);
        r.views[kept[m]].rejected = text;
      }
    kept = inliers;
    c = run(kept);
  }
  for (size_t m = 0; m < kept.size(); ++m) {
    r.views[kept[m]].used = true;
    r.views[kept[m]].error_px = c.per_view[m];
  }

  r.rms_px = c.rms;
  r.camera.image_size = size;
  r.camera.fx = c.camera_matrix.at<double>(0, 0);
  r.camera.fy = c.camera_matrix.at<double>(1, 1);
  r.camera.cx = c.camera_matrix.at<double>(0, 2);
  r.camera.cy = c.camera_matrix.at<double>(1, 2);
  r.camera.distortion.assign(c.distortion.begin<double>(), c.distortion.end<double>());
  finish();
  return r;
}

}  // namespace demoplan::perception
