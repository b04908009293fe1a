#include "perception/tracking/appearance_error.h"

#include <cmath>

#include <opencv2/imgproc.hpp>

#include "perception/render/rasterizer.h"

namespace demoplan::perception {

double appearance_error(const cv::Mat& image, const PinholeIntrinsics& K, const Pose& world_T_camera,
                        const RenderMesh& mesh, const Pose& camera_T_part, const OcclusionMap& occlusion, int part,
                        int min_pixels) {
  const PrintDifference d = print_difference(image, K, world_T_camera, mesh, camera_T_part, occlusion, part);
  return d.pixels < min_pixels ? -1.0 : d.error;
}

PrintDifference print_difference(const cv::Mat& image, const PinholeIntrinsics& K, const Pose& world_T_camera,
                                 const RenderMesh& mesh, const Pose& camera_T_part, const OcclusionMap& occlusion,
                                 int part, double outlier) {
  PrintDifference out;
  // Drawn only over the window its bounds cover in the image (the whole image when a corner of
  // them is behind the camera).
  cv::Rect window(cv::Point(0, 0), image.size());
  {
    const Eigen::AlignedBox3f b = mesh.bounds();
    double u0 = 1e9, v0 = 1e9, u1 = -1e9, v1 = -1e9;
    bool in_front = true;
    for (int i = 0; i < 8 && in_front; ++i) {
      const Eigen::Vector3d p = camera_T_part * b.corner(static_cast<Eigen::AlignedBox3f::CornerType>(i)).cast<double>();
      in_front = p.z() > 1e-3;
      const double u = K.fx * p.x() / p.z() + K.cx, v = K.fy * p.y() / p.z() + K.cy;
      u0 = std::min(u0, u), v0 = std::min(v0, v), u1 = std::max(u1, u), v1 = std::max(v1, v);
    }
    if (in_front)
      window &= cv::Rect(cv::Point(static_cast<int>(std::floor(u0)) - 3, static_cast<int>(std::floor(v0)) - 3),
                         cv::Point(static_cast<int>(std::ceil(u1)) + 4, static_cast<int>(std::ceil(v1)) + 4));
    if (window.empty()) return out;
  }
  // Drawn from where the camera stands, so that its faces are shaded as the world's light shades them.
  Rasterizer r(window.size(), K.fx, K.fy, K.cx - window.x, K.cy - window.y, world_T_camera);
  r.clear({0, 0, 0}, {0, 0, 0});
  r.draw(mesh, world_T_camera * camera_T_part);
  cv::Mat shows = r.depth() < 1e9f;
  const cv::Rect local = cv::boundingRect(shows);
  if (local.empty()) return out;
  const cv::Rect box = local + window.tl();  // in the image
  // Its rim left out: the blur there mixes in what surrounds it, in the image and not in the drawing.
  cv::erode(shows, shows, cv::getStructuringElement(cv::MORPH_ELLIPSE, cv::Size(7, 7)));
  cv::Mat seen, drawn;
  cv::blur(image(box), seen, cv::Size(5, 5));
  cv::blur(r.color()(local), drawn, cv::Size(5, 5));
  std::vector<cv::Point> pixels;
  cv::Vec3d seen_sum(0, 0, 0), drawn_sum(0, 0, 0);
  for (int y = 0; y < box.height; ++y)
    for (int x = 0; x < box.width; ++x) {
      if (!shows.at<uchar>(local.y + y, local.x + x)) continue;
      if (!occlusion.empty() && occlusion.hides(box.x + x, box.y + y, part, r.depth().at<float>(local.y + y, local.x + x)))
        continue;
      pixels.emplace_back(x, y);
      seen_sum += cv::Vec3d(seen.at<cv::Vec3b>(y, x));
      drawn_sum += cv::Vec3d(drawn.at<cv::Vec3b>(y, x));
    }
  if (pixels.empty()) return out;
  cv::Vec3d gain;
  for (int c = 0; c < 3; ++c) gain[c] = drawn_sum[c] > 0 ? seen_sum[c] / drawn_sum[c] : 1.0;
  double error = 0.0;
  for (const auto& p : pixels) {
    const cv::Vec3b& a = seen.at<cv::Vec3b>(p);
    const cv::Vec3b& b = drawn.at<cv::Vec3b>(p);
    double e = 0.0;
    for (int c = 0; c < 3; ++c) e += std::abs(a[c] - gain[c] * b[c]);
    error += e;
    if (outlier > 0 && e > 3.0 * outlier) ++out.outliers;
  }
  out.pixels = static_cast<int>(pixels.size());
  out.error = error / (3.0 * static_cast<double>(pixels.size()));
  return out;
}

PrintTurn turn_to_print(const cv::Mat& image, const PinholeIntrinsics& K, const Pose& world_T_camera,
                        const RenderMesh& mesh, const Pose& camera_T_part, const Eigen::Vector3d& centre,
                        const OcclusionMap& occlusion, int part, double turn, double min_turn) {
  PrintTurn fit;
  fit.camera_T_part = camera_T_part;
  const Pose world_T_part = world_T_camera * camera_T_part;
  const Eigen::Vector3d c = world_T_part * centre;
  auto turned = [&](double angle) {
    Pose R = Pose::Identity();
    R.linear() = Eigen::AngleAxisd(angle, Eigen::Vector3d::UnitZ()).toRotationMatrix();
    R.translation() = c - R.linear() * c;
    return Pose(world_T_camera.inverse() * R * world_T_part);
  };
  double best = appearance_error(image, K, world_T_camera, mesh, camera_T_part, occlusion, part);
  fit.error_before = best;
  if (best < 0) return fit;
  double angle = 0.0;
  for (double a = turn; a >= min_turn; a /= 2)
    for (bool moved = true; moved;) {
      moved = false;
      for (const double next : {angle + a, angle - a})
        if (const double e = appearance_error(image, K, world_T_camera, mesh, turned(next), occlusion, part); e >= 0 && e < best)
          best = e, angle = next, moved = true;
    }
  fit.camera_T_part = turned(angle);
  fit.error = best;
  return fit;
}

}  // namespace demoplan::perception
