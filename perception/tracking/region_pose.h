#pragma once
// One frame of region-based pose tracking for one part (after SRT3D, Stoiber et al. 2022):
// lines through the projected contour of the part along its normals; on each line the
// probability of every position of the silhouette's edge, from the part's and its
// surroundings' colour models; then Gauss-Newton steps that move the projected contour to where
// the edges most probably are. Coarse to fine: long lines of coarse samples first.
#include <vector>

#include <opencv2/core.hpp>

#include "core/geometry/se3.h"
#include "perception/tracking/color_histograms.h"
#include "perception/tracking/contour_model.h"

namespace demoplan::perception {

struct PinholeIntrinsics {
  double fx = 1000, fy = 1000, cx = 640, cy = 360;
};

// Which tracked part or furniture covers each pixel and how far away (rendered at the current
// estimates): lines of one part where something nearer covers the part are left out.
struct OcclusionMap {
  static constexpr int kFurniture = 255;
  static constexpr float kMargin = 0.01f;  // m: nearer by less does not hide
  cv::Mat labels;  // CV_8U, 0: nothing, k + 1: part k, kFurniture: the furniture
  cv::Mat depth;   // CV_32F, m
  double scale = 0.5;  // map pixels per image pixel

  bool empty() const { return labels.empty(); }
  // True when a part other than `part` is in front of depth `z` at image pixel (x, y).
  // (Here, not in the .cpp: it is asked for every sample of every line.)
  bool hides(double x, double y, int part, float z) const {
    const int u = static_cast<int>(x * scale), v = static_cast<int>(y * scale);
    if (u < 0 || v < 0 || u >= labels.cols || v >= labels.rows) return false;
    const int label = labels.at<uchar>(v, u);
    return label != 0 && label != part + 1 && depth.at<float>(v, u) < z - kMargin;
  }
};

// A point on the part (its frame) and where the image shows it (surface_flow.h).
struct SurfacePoint {
  Eigen::Vector3d part;
  Eigen::Vector2d pixel;
};

struct RegionTrackingOptions {
  std::vector<int> scales{6, 4, 2, 2, 1, 1};  // px per line sample, one correspondence pass each
  int newton_steps = 2;                 // per pass
  int line_samples = 10;                // per side of the contour
  int window = 4;                       // samples per side scored for one edge position
  double step_amplitude = 0.43;         // of the smoothed step from part to surroundings
  double step_slope = 0.5;              // samples
  double robust_scale = 3.0;            // standard deviations where a line's weight halves
  double tikhonov_rotation = 1e3;       // regularisation of each step (rad^-2, in the data's units)
  double tikhonov_translation = 3e4;    // (m^-2)
  int learn_pixels = 12;                // each side of the contour, for the colour models
  double point_sigma = 1.5;             // px, of a surface point's image position (Cauchy-weighted)
};

struct RegionFrameResult {
  Pose camera_T_part = Pose::Identity();
  int lines = 0;         // contour points of the view
  int used_lines = 0;    // inside the image, not hidden, with an edge found (last pass)
  int hidden_lines = 0;  // where something nearer covers the part (last pass)
  double contrast = 0.0;  // mean P(part) inside minus outside the contour, -1..1 (last pass)
};

// Refines `camera_T_part` on `image` (BGR, undistorted). `part` is the part's label in `occlusion`.
// `hold_depth`: the part's centre keeps its distance along its line of sight (a part at rest:
// the silhouette's size is the weakest cue, and small edge biases would let it drift).
// `points`: surface points seen in this frame, fitted together with the contour.
RegionFrameResult track_region(const cv::Mat& image, const PinholeIntrinsics& camera, const ContourModel& model,
                               const ColorHistograms& colors, const Pose& camera_T_part, const OcclusionMap& occlusion,
                               int part, const RegionTrackingOptions& options = {}, bool hold_depth = false,
                               const std::vector<SurfacePoint>& points = {});

// How well the part stands out at `camera_T_part`: the mean over its contour points of P(part)
// on `samples` pixels inside minus `samples` outside, `step` px apart (-1..1; 0 when no point
// is in the image). Cheap: for scoring candidate poses in a search.
double contour_contrast(const cv::Mat& image, const PinholeIntrinsics& camera, const ContourModel& model,
                        const ColorHistograms& colors, const Pose& camera_T_part, int samples = 4, int step = 2);

// Adds the pixels along the contour at `camera_T_part` to the colour models and updates them;
// the part's own model only with `foreground` (not while a hand holds it: its colours next to
// the part would creep into the part's).
void learn_colors(const cv::Mat& image, const PinholeIntrinsics& camera, const ContourModel& model,
                  const Pose& camera_T_part, const OcclusionMap& occlusion, int part, ColorHistograms& colors,
                  const RegionTrackingOptions& options = {}, bool foreground = true);

}  // namespace demoplan::perception
