#include "perception/tracking/surface_flow.h"

#include <opencv2/imgproc.hpp>
#include <opencv2/video/tracking.hpp>

namespace demoplan::perception {

std::vector<std::vector<SurfacePoint>> follow_surface_points(const cv::Mat& last_gray, const cv::Mat& gray,
                                                             const OcclusionMap& last, const std::vector<Pose>& camera_T_part,
                                                             const std::vector<bool>& follow, const PinholeIntrinsics& K,
                                                             const SurfaceFlowOptions& o) {
  std::vector<std::vector<SurfacePoint>> out(camera_T_part.size());
  if (last.empty() || last_gray.empty()) return out;
  std::vector<cv::Point2f> from;
  std::vector<std::pair<int, Eigen::Vector3d>> source;  // part, point in its frame
  const double s = last.scale;
  const cv::Mat kernel = cv::getStructuringElement(cv::MORPH_RECT, cv::Size(2 * o.border + 1, 2 * o.border + 1));
  for (size_t k = 0; k < camera_T_part.size(); ++k) {
    if (!follow[k]) continue;
    cv::Mat mask = last.labels == static_cast<int>(k + 1);
    cv::erode(mask, mask, kernel);
    const cv::Rect box = cv::boundingRect(mask);
    if (box.area() == 0) continue;
    // Corners in the full-resolution image, within the part's box; the mask at its scale.
    const cv::Rect full(cv::Point(int(box.x / s), int(box.y / s)), cv::Point(int((box.x + box.width) / s), int((box.y + box.height) / s)));
    const cv::Rect roi = full & cv::Rect(0, 0, last_gray.cols, last_gray.rows);
    if (roi.area() < 16) continue;
    cv::Mat roi_mask;
    cv::resize(mask(box), roi_mask, roi.size(), 0, 0, cv::INTER_NEAREST);
    std::vector<cv::Point2f> corners;
    cv::goodFeaturesToTrack(last_gray(roi), corners, o.corners, 0.01, o.min_distance, roi_mask);
    const Pose part_T_camera = camera_T_part[k].inverse();
    for (auto c : corners) {
      c += cv::Point2f(float(roi.x), float(roi.y));
      const int mx = int(c.x * s), my = int(c.y * s);
      if (mx < 0 || my < 0 || mx >= last.depth.cols || my >= last.depth.rows) continue;
      const double z = last.depth.at<float>(my, mx);
      if (!(z > 0.05 && z < 1e6)) continue;
      const Eigen::Vector3d in_camera((c.x - K.cx) * z / K.fx, (c.y - K.cy) * z / K.fy, z);
      from.push_back(c);
      source.push_back({int(k), part_T_camera * in_camera});
    }
  }
  if (from.empty()) return out;
  std::vector<cv::Point2f> to;
  std::vector<uchar> status;
  std::vector<float> error;
  cv::calcOpticalFlowPyrLK(last_gray, gray, from, to, status, error, cv::Size(o.window, o.window), o.levels);
  for (size_t i = 0; i < from.size(); ++i)
    if (status[i] && error[i] < o.max_error)
      out[source[i].first].push_back({source[i].second, Eigen::Vector2d(to[i].x, to[i].y)});
  return out;
}

}  // namespace demoplan::perception
