#include "perception/synthetic/board_video.h"

#include <chrono>
#include <cmath>
#include <filesystem>
#include <stdexcept>

#include <opencv2/calib3d.hpp>
#include <opencv2/imgproc.hpp>

#include "perception/video/video_writer.h"

namespace demoplan::perception {

namespace fs = std::filesystem;

namespace {

constexpr double kPageSquarePx = 160;  // page pixels a square: finer than any view shows it
constexpr unsigned char kBackground = 110;

bool inside(const Camera& camera, const Eigen::Vector3d& p, double margin) {
  if (p.z() <= 0.05) return false;
  const cv::Point2d q = camera.project(p);
  return q.x >= margin && q.y >= margin && q.x <= camera.image_size.width - 1 - margin &&
         q.y <= camera.image_size.height - 1 - margin;
}

}  // namespace

Camera board_video_truth_camera() {
  Camera c;
  c.image_size = {1280, 720};
  c.fx = c.fy = 1100;
  c.cx = 640;
  c.cy = 360;
  return c;
}

std::vector<Pose> board_view_poses(const CharucoBoard& board, const Camera& camera, int count, unsigned seed) {
  cv::RNG rng(seed * 7919u + 13u);
  const double w = board.width(), h = board.height();
  const double W = camera.image_size.width, H = camera.image_size.height;
  std::vector<Pose> poses;
  while (int(poses.size()) < count) {
    const size_t before = poses.size();
    for (int attempt = 0; attempt < 1000; ++attempt) {
      const double tilt = rng.uniform(15.0, 60.0) * M_PI / 180, axis = rng.uniform(0.0, 2 * M_PI);
      const double turn = rng.uniform(-25.0, 25.0) * M_PI / 180;
      const double distance = rng.uniform(0.35, 0.75);
      const double u = rng.uniform(0.3 * W, 0.7 * W), v = rng.uniform(0.3 * H, 0.7 * H);
      Pose T = Pose::Identity();
      // Board facing the camera (its z, into the board, along the optical axis), then tilted.
      T.linear() = (Eigen::AngleAxisd(turn, Eigen::Vector3d::UnitZ()) *
                    Eigen::AngleAxisd(tilt, Eigen::Vector3d(std::cos(axis), std::sin(axis), 0)))
                       .toRotationMatrix();
      const Eigen::Vector3d centre = distance * Eigen::Vector3d((u - camera.cx) / camera.fx, (v - camera.cy) / camera.fy, 1);
      T.translation() = centre - T.linear() * Eigen::Vector3d(w / 2, h / 2, 0);
      bool ok = true;
      for (double x : {0.0, w})
        for (double y : {0.0, h}) ok = ok && inside(camera, T * Eigen::Vector3d(x, y, 0), 10);
      if (ok) {
        poses.push_back(T);
        break;
      }
    }
    if (poses.size() == before)
      throw std::invalid_argument("the board does not fit in the camera's image 0.35-0.75 m away");
  }
  return poses;
}

BoardViewRenderer::BoardViewRenderer(const CharucoBoard& board, const Camera& camera) : camera_(camera) {
  page_ = printable_board(board, kPageSquarePx / (board.square_length * 1000) * 25.4);
  // Print contrast, not pure black and white, so that noise is not clipped.
  page_.image.convertTo(page_.image, CV_8U, 195.0 / 255.0, 30);
  // Pixel centre (i, j) of the 2x image is at ((j - 0.5) / 2, (i - 0.5) / 2) in the frame (the
  // 2x2 block that INTER_AREA averages into one pixel): its ray, distortion removed.
  const cv::Size hi(2 * camera.image_size.width, 2 * camera.image_size.height);
  std::vector<cv::Point2f> pixels;
  pixels.reserve(size_t(hi.area()));
  for (int i = 0; i < hi.height; ++i)
    for (int j = 0; j < hi.width; ++j) pixels.emplace_back(float((j - 0.5) / 2), float((i - 0.5) / 2));
  std::vector<cv::Point2f> rays;
  cv::undistortPoints(pixels, rays, camera.camera_matrix(), camera.distortion_coefficients());
  rays_ = cv::Mat(rays, true).reshape(2, hi.height);
}

cv::Mat BoardViewRenderer::render(const Pose& camera_T_board, const Degradation& degradation, cv::RNG& rng) const {
  // A ray (x, y, 1) meets the board plane at board point B^-1 (x, y, 1), B = [r1 r2 t].
  const Eigen::Matrix3d R = camera_T_board.linear();
  Eigen::Matrix3d B;
  B << R.col(0), R.col(1), camera_T_board.translation();
  Eigen::Matrix3d A;
  A << page_.px_per_m_x, 0, page_.offset.x, 0, page_.px_per_m_y, page_.offset.y, 0, 0, 1;
  const Eigen::Matrix3d ray_to_page = A * B.inverse();
  cv::Matx33d M;
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) M(r, c) = ray_to_page(r, c);
  cv::Mat map, hi, frame;
  cv::perspectiveTransform(rays_, map, M);
  cv::remap(page_.image, hi, map, cv::noArray(), cv::INTER_LINEAR, cv::BORDER_CONSTANT, cv::Scalar(kBackground));
  cv::resize(hi, frame, camera_.image_size, 0, 0, cv::INTER_AREA);
  cv::cvtColor(frame, frame, cv::COLOR_GRAY2BGR);
  degrade(frame, degradation, rng);
  return frame;
}

BoardVideoOutput write_board_video(const BoardVideoOptions& o, const std::string& out_dir) {
  const auto t0 = std::chrono::steady_clock::now();
  fs::create_directories(out_dir);
  BoardVideoOutput out;
  out.video = (fs::path(out_dir) / "calibration.mp4").string();
  out.board = (fs::path(out_dir) / "board.json").string();
  out.camera_truth = (fs::path(out_dir) / "camera_truth.json").string();
  const std::vector<Pose> poses = board_view_poses(o.board, o.camera, o.views, o.seed);
  const BoardViewRenderer renderer(o.board, o.camera);
  VideoWriter writer(out.video, o.fps, o.camera.image_size, o.fourcc);
  cv::RNG blur_rng(o.seed * 2654435761u + 29u);
  for (size_t k = 0; k < poses.size(); ++k) {
    if (o.cancel && o.cancel->load()) {
      out.cancelled = true;
      return out;  // the writer removes its partial file
    }
    // A hand-held board moves: each view has its own blur direction.
    const Degradation d{o.noise_sigma, o.blur_px, blur_rng.uniform(0.0, M_PI)};
    cv::RNG noise_rng(o.seed * 1000003u + static_cast<unsigned>(k));
    writer.write(renderer.render(poses[k], d, noise_rng));
    if (o.progress) o.progress(int(k) + 1, int(poses.size()));
  }
  writer.finish();
  out.frames = writer.frames_written();
  save_charuco_board(out.board, o.board);
  save_camera(out.camera_truth, o.camera);
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return out;
}

}  // namespace demoplan::perception
