#include "perception/tracking/region_pose.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>

#include <Eigen/Cholesky>

namespace demoplan::perception {

namespace {

constexpr double kNear = 0.05;       // m: contour points nearer the camera are not used

Eigen::Matrix3d skew(const Eigen::Vector3d& v) {
  Eigen::Matrix3d S;
  S << 0, -v.z(), v.y(), v.z(), 0, -v.x(), -v.y(), v.x(), 0;
  return S;
}

// A contour point projected with the pose its line was set up at.
struct Projected {
  Eigen::Vector3d part;    // point, part frame
  Eigen::Vector3d camera;  // point, camera frame
  Eigen::Vector2d pixel;
  Eigen::Vector2d normal;  // unit, image
  double px_per_m = 0.0;   // image scale at the point
};

bool project(const ContourPoint& cp, const Pose& T, const PinholeIntrinsics& K, Projected& p) {
  p.part = cp.position.cast<double>();
  p.camera = T * p.part;
  if (p.camera.z() < kNear) return false;
  const double iz = 1.0 / p.camera.z();
  p.pixel = {K.fx * p.camera.x() * iz + K.cx, K.fy * p.camera.y() * iz + K.cy};
  const Eigen::Vector3d n = T.linear() * cp.normal.cast<double>();
  // Image direction of the normal: the projection's Jacobian applied to it.
  const Eigen::Vector2d d(K.fx * iz * (n.x() - p.camera.x() * iz * n.z()), K.fy * iz * (n.y() - p.camera.y() * iz * n.z()));
  if (d.norm() < 1e-9) return false;
  p.normal = d.normalized();
  p.px_per_m = 0.5 * (K.fx + K.fy) * iz;
  return true;
}

bool pixel_at(const cv::Mat& image, const Eigen::Vector2d& q, cv::Vec3b& out) {
  // The pixel lround would pick, without its library call (asked for every sample of a line).
  if (!(q.x() > -0.5 && q.y() > -0.5 && q.x() < image.cols - 0.5 && q.y() < image.rows - 0.5)) return false;
  out = image.at<cv::Vec3b>(static_cast<int>(q.y() + 0.5), static_cast<int>(q.x() + 0.5));
  return true;
}

// One correspondence line: the edge's position along the normal as a mean and a variance (px).
struct Line {
  Eigen::Vector3d part;
  Eigen::Vector2d centre, normal;
  double mean = 0.0, variance = 1.0;
};

// log(hf f + (1 - hf)(1 - f)), a sample's term in an edge candidate's score, for a colour bin (its
// probability f) and an offset from the edge (the step's hf there): the same few colours recur
// on every line, and a logarithm per sample took a tenth of an extraction. Kept for one pass
// (its colours and step fixed), per thread; stamped rather than cleared.
class SampleLogMemo {
public:
  void start(int offsets) {
    offsets_ = offsets;
    const size_t size = static_cast<size_t>(ColorHistograms::kBins) * offsets;
    if (stamp_.size() != size) stamp_.assign(size, 0), value_.resize(size), pass_ = 0;
    if (++pass_ == 0) std::fill(stamp_.begin(), stamp_.end(), 0u), pass_ = 1;
  }
  double operator()(int bin, int offset, double hf, double f) {
    const size_t key = static_cast<size_t>(bin) * offsets_ + offset;
    if (stamp_[key] != pass_) stamp_[key] = pass_, value_[key] = std::log(hf * f + (1.0 - hf) * (1.0 - f));
    return value_[key];
  }

private:
  int offsets_ = 0;
  std::uint32_t pass_ = 0;
  std::vector<std::uint32_t> stamp_;
  std::vector<double> value_;
};

struct Pass {
  std::vector<Line> lines;
  int hidden = 0;
  double contrast_sum = 0.0;
  int contrast_lines = 0;
};

Pass correspondence_pass(const cv::Mat& image, const PinholeIntrinsics& K, const ContourView& view,
                         const ColorHistograms& colors, const Pose& T, const OcclusionMap& occlusion, int part,
                         int scale, const RegionTrackingOptions& o) {
  Pass pass;
  const int N = o.line_samples, W = std::min(o.window, N - 1), M = N - W;
  std::vector<float> pf(2 * N);
  std::vector<int> bins(2 * N);
  thread_local SampleLogMemo sample_log;
  sample_log.start(2 * W);
  std::vector<double> log_p(2 * M + 1);
  // The smoothed step at each offset of a sample from a candidate edge (the same for every line).
  std::vector<double> step(2 * W);
  for (int d = -W; d < W; ++d) step[d + W] = 0.5 - o.step_amplitude * std::tanh((d + 0.5) / (2.0 * o.step_slope));
  for (const auto& cp : view.points) {
    Projected p;
    if (!project(cp, T, K, p)) continue;
    const double inner_px = cp.inner * p.px_per_m, outer_px = cp.outer * p.px_per_m;
    bool ok = true, hidden = false;
    for (int i = -N; i < N && ok; ++i) {
      const double x = (i + 0.5) * scale;
      const Eigen::Vector2d q = p.pixel + x * p.normal;
      cv::Vec3b c;
      if (!pixel_at(image, q, c)) ok = false;
      // Hidden where the line crosses the part: whatever is in front outside it is background.
      else if (i < 0 && !occlusion.empty() && occlusion.hides(q.x(), q.y(), part, static_cast<float>(p.camera.z())))
        ok = false, hidden = true;
      else bins[i + N] = ColorHistograms::bin(c), pf[i + N] = colors.bin_probability(bins[i + N]);
    }
    pass.hidden += hidden;
    if (!ok) continue;
    // Each candidate edge position d_k = k * scale, scored on the 2W samples around it: part
    // colours before the edge, surroundings after it, through a smoothed step.
    double best = -1e300;
    for (int k = -M; k <= M; ++k) {
      double s = 0.0;
      for (int i = k - W; i < k + W; ++i) {
        const double x = (i + 0.5) * scale;
        if (x < -inner_px || x > outer_px + scale) continue;  // beyond the silhouette's own extent
        const double hf = step[i - k + W];
        const double f = pf[i + N];
        s += sample_log(bins[i + N], i - k + W, hf, f);
      }
      log_p[k + M] = s;
      best = std::max(best, s);
    }
    double sum = 0.0, mean = 0.0;
    for (int k = -M; k <= M; ++k) {
      const double w = std::exp(log_p[k + M] - best);
      sum += w;
      mean += w * k * scale;
    }
    mean /= sum;
    double variance = 0.0;
    for (int k = -M; k <= M; ++k) variance += std::exp(log_p[k + M] - best) / sum * std::pow(k * scale - mean, 2);
    variance = std::max(variance, 0.25 * scale * scale);
    // A flat distribution: the line shows no edge (all part, all surroundings, or an occluder).
    if (std::sqrt(variance) > 0.5 * M * scale) continue;
    pass.lines.push_back({p.part, p.pixel, p.normal, mean, variance});
    // Contrast at the line's centre: the part's probability inside minus outside.
    double in = 0.0, out = 0.0;
    for (int i = 0; i < N; ++i) in += pf[N - 1 - i], out += pf[N + i];
    pass.contrast_sum += (in - out) / N;
    ++pass.contrast_lines;
  }
  return pass;
}

// Gauss-Newton steps moving the contour points' projections to the lines' edge estimates.
// `held_ray`: when set, the centre's moves along this camera-frame direction are taken out.
Pose newton_steps(const Pass& pass, const std::vector<SurfacePoint>& points, const PinholeIntrinsics& K,
                  const Eigen::Vector3d& centre, Pose T, const RegionTrackingOptions& o,
                  const std::optional<Eigen::Vector3d>& held_ray) {
  for (int step = 0; step < o.newton_steps; ++step) {
    Eigen::Matrix<double, 6, 6> A = Eigen::Matrix<double, 6, 6>::Zero();
    Eigen::Matrix<double, 6, 1> b = Eigen::Matrix<double, 6, 1>::Zero();
    const Eigen::Matrix3d R = T.linear();
    for (const auto& l : pass.lines) {
      const Eigen::Vector3d X = T * l.part;
      if (X.z() < kNear) continue;
      const double iz = 1.0 / X.z();
      const Eigen::Vector2d u(K.fx * X.x() * iz + K.cx, K.fy * X.y() * iz + K.cy);
      Eigen::Matrix<double, 2, 3> Jp;
      Jp << K.fx * iz, 0, -K.fx * X.x() * iz * iz, 0, K.fy * iz, -K.fy * X.y() * iz * iz;
      Eigen::Matrix<double, 3, 6> Jx;
      Jx.leftCols<3>() = -R * skew(l.part - centre);
      Jx.rightCols<3>() = R;
      const Eigen::Matrix<double, 1, 6> J = l.normal.transpose() * Jp * Jx;
      const double r = l.normal.dot(u - l.centre) - l.mean;
      // Cauchy weights: lines whose edge lies far off the others' consensus (an occluder's
      // edge, a hand's) pull less.
      const double w = 1.0 / (l.variance * (1.0 + r * r / (o.robust_scale * o.robust_scale * l.variance)));
      A.noalias() += w * J.transpose() * J;
      b.noalias() += w * r * J.transpose();
    }
    const double point_variance = o.point_sigma * o.point_sigma;
    for (const auto& p : points) {
      const Eigen::Vector3d X = T * p.part;
      if (X.z() < kNear) continue;
      const double iz = 1.0 / X.z();
      const Eigen::Vector2d r(K.fx * X.x() * iz + K.cx - p.pixel.x(), K.fy * X.y() * iz + K.cy - p.pixel.y());
      Eigen::Matrix<double, 2, 3> Jp;
      Jp << K.fx * iz, 0, -K.fx * X.x() * iz * iz, 0, K.fy * iz, -K.fy * X.y() * iz * iz;
      Eigen::Matrix<double, 3, 6> Jx;
      Jx.leftCols<3>() = -R * skew(p.part - centre);
      Jx.rightCols<3>() = R;
      const Eigen::Matrix<double, 2, 6> J = Jp * Jx;
      // Cauchy weights: a point that slid off the part (onto a hand, an edge) pulls little.
      const double w = 1.0 / (point_variance * (1.0 + r.squaredNorm() / (o.robust_scale * o.robust_scale * point_variance)));
      A.noalias() += w * J.transpose() * J;
      b.noalias() += w * J.transpose() * r;
    }
    for (int i = 0; i < 3; ++i) A(i, i) += o.tikhonov_rotation, A(i + 3, i + 3) += o.tikhonov_translation;
    Eigen::Matrix<double, 6, 1> delta = -A.ldlt().solve(b);
    if (!delta.allFinite()) break;
    if (held_ray) {
      // The step moves the centre by R * v (rotations turn about it): keep that off the ray.
      const Eigen::Vector3d along = R.transpose() * *held_ray;
      delta.tail<3>() -= along * along.dot(delta.tail<3>());
    }
    const Eigen::Vector3d w = delta.head<3>();
    Pose M = Pose::Identity();
    if (w.norm() > 1e-12) M.linear() = Eigen::AngleAxisd(w.norm(), w.normalized()).toRotationMatrix();
    M.translation() = centre - M.linear() * centre + delta.tail<3>();
    T = T * M;
  }
  return T;
}

}  // namespace

RegionFrameResult track_region(const cv::Mat& image, const PinholeIntrinsics& K, const ContourModel& model,
                               const ColorHistograms& colors, const Pose& camera_T_part, const OcclusionMap& occlusion,
                               int part, const RegionTrackingOptions& o, bool hold_depth,
                               const std::vector<SurfacePoint>& points) {
  RegionFrameResult result;
  Pose T = camera_T_part;
  std::optional<Eigen::Vector3d> held_ray;
  if (hold_depth) held_ray = (T * model.centre()).normalized();
  for (const int scale : o.scales) {
    const ContourView& view = model.view_from(T);
    const Pass pass = correspondence_pass(image, K, view, colors, T, occlusion, part, scale, o);
    result.lines = static_cast<int>(view.points.size());
    result.used_lines = static_cast<int>(pass.lines.size());
    result.hidden_lines = pass.hidden;
    result.contrast = pass.contrast_lines ? pass.contrast_sum / pass.contrast_lines : 0.0;
    if (pass.lines.size() + points.size() < 6) continue;  // too little to fix six degrees of freedom
    T = newton_steps(pass, points, K, model.centre(), T, o, held_ray);
  }
  result.camera_T_part = T;
  return result;
}

double contour_contrast(const cv::Mat& image, const PinholeIntrinsics& K, const ContourModel& model,
                        const ColorHistograms& colors, const Pose& T, int samples, int step) {
  const ContourView& view = model.view_from(T);
  double sum = 0.0;
  int lines = 0;
  for (size_t j = 0; j < view.points.size(); j += 2) {  // every other point: enough for a score
    Projected p;
    if (!project(view.points[j], T, K, p)) continue;
    double in = 0.0, out = 0.0;
    bool ok = true;
    for (int i = 0; i < samples && ok; ++i) {
      cv::Vec3b a, b;
      ok = pixel_at(image, p.pixel - (0.5 + i * step) * p.normal, a) && pixel_at(image, p.pixel + (0.5 + i * step) * p.normal, b);
      if (ok) in += colors.foreground_probability(a), out += colors.foreground_probability(b);
    }
    if (!ok) continue;
    sum += (in - out) / samples;
    ++lines;
  }
  return lines ? sum / lines : 0.0;
}

void learn_colors(const cv::Mat& image, const PinholeIntrinsics& K, const ContourModel& model, const Pose& T,
                  const OcclusionMap& occlusion, int part, ColorHistograms& colors, const RegionTrackingOptions& o,
                  bool foreground) {
  const ContourView& view = model.view_from(T);
  for (const auto& cp : view.points) {
    Projected p;
    if (!project(cp, T, K, p)) continue;
    const double inner_px = cp.inner * p.px_per_m, outer_px = cp.outer * p.px_per_m;
    // From the pixels next to the edge on: with chroma subsampled and blurred by a codec, those
    // carry mixed colours, and each side must learn its own (else the silhouette looks a pixel
    // larger than it is, for parts whose colours stand out more than their surroundings').
    for (int i = 1; i <= o.learn_pixels; ++i) {
      cv::Vec3b c;
      const Eigen::Vector2d qi = p.pixel - (i - 0.5) * p.normal, qo = p.pixel + (i - 0.5) * p.normal;
      const auto z = static_cast<float>(p.camera.z());
      if (foreground && i < inner_px && pixel_at(image, qi, c) && (occlusion.empty() || !occlusion.hides(qi.x(), qi.y(), part, z)))
        colors.add_foreground(c);
      if (i < outer_px && pixel_at(image, qo, c)) colors.add_background(c);
    }
  }
  colors.update();
}

}  // namespace demoplan::perception
