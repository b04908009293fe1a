#include "perception/tracking/appearance_error.h"

#include <cmath>

#include <opencv2/imgproc.hpp>

#include "perception/render/rasterizer.h"

namespace demoplan::perception {

double appearance_error(const cv::Mat& image, const PinholeIntrinsics& K, const Pose& world_T_camera,
                        const RenderMesh& mesh, const Pose& camera_T_part, const OcclusionMap& occlusion, int part,
                        int min_pixels) {
  // Drawn from where the camera stands, so that its faces are shaded as the world's light shades them.
  Rasterizer r(image.size(), K.fx, K.fy, K.cx, K.cy, world_T_camera);
  r.clear({0, 0, 0}, {0, 0, 0});
  r.draw(mesh, world_T_camera * camera_T_part);
  cv::Mat shows = r.depth() < 1e9f;
  const cv::Rect box = cv::boundingRect(shows);
  if (box.area() < min_pixels) return -1.0;
  // Its rim left out: the blur there mixes in what surrounds it, in the image and not in the drawing.
  cv::erode(shows, shows, cv::getStructuringElement(cv::MORPH_ELLIPSE, cv::Size(7, 7)));
  cv::Mat seen, drawn;
  cv::blur(image(box), seen, cv::Size(5, 5));
  cv::blur(r.color()(box), drawn, cv::Size(5, 5));
  std::vector<cv::Point> pixels;
  cv::Vec3d seen_sum(0, 0, 0), drawn_sum(0, 0, 0);
  for (int y = 0; y < box.height; ++y)
    for (int x = 0; x < box.width; ++x) {
      const int u = box.x + x, v = box.y + y;
      if (!shows.at<uchar>(v, u)) continue;
      if (!occlusion.empty() && occlusion.hides(u, v, part, r.depth().at<float>(v, u))) continue;
      pixels.emplace_back(x, y);
      seen_sum += cv::Vec3d(seen.at<cv::Vec3b>(y, x));
      drawn_sum += cv::Vec3d(drawn.at<cv::Vec3b>(y, x));
    }
  if (static_cast<int>(pixels.size()) < min_pixels) return -1.0;
  cv::Vec3d gain;
  for (int c = 0; c < 3; ++c) gain[c] = drawn_sum[c] > 0 ? seen_sum[c] / drawn_sum[c] : 1.0;
  double error = 0.0;
  for (const auto& p : pixels) {
    const cv::Vec3b& a = seen.at<cv::Vec3b>(p);
    const cv::Vec3b& b = drawn.at<cv::Vec3b>(p);
    for (int c = 0; c < 3; ++c) error += std::abs(a[c] - gain[c] * b[c]);
  }
  return error / (3.0 * static_cast<double>(pixels.size()));
}

}  // namespace demoplan::perception
