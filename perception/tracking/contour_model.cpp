#include "perception/tracking/contour_model.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <opencv2/imgproc.hpp>

#include "perception/camera/look_at.h"
#include "perception/render/rasterizer.h"

namespace demoplan::perception {

namespace {

// Steps along the unit image direction d from p until the mask value changes from `inside`;
// returns the number of steps taken (at most `max_steps`).
int run_length(const cv::Mat& mask, Eigen::Vector2d p, const Eigen::Vector2d& d, bool inside, int max_steps) {
  for (int k = 1; k <= max_steps; ++k) {
    p += d;
    const int x = static_cast<int>(std::lround(p.x())), y = static_cast<int>(std::lround(p.y()));
    if (x < 0 || y < 0 || x >= mask.cols || y >= mask.rows) return inside ? k - 1 : max_steps;
    if ((mask.at<uchar>(y, x) != 0) != inside) return k - 1;
  }
  return max_steps;
}

ContourView render_view(const RenderMesh& silhouette, const Eigen::Vector3d& direction, const Eigen::Vector3d& centre,
                        double radius, const ContourModelOptions& o) {
  const double distance = std::max(10.0 * radius, 2.0);  // about where a camera watches from
  const double f = 0.85 * 0.5 * o.image_size * distance / radius;  // the bounding sphere fills 85 %
  const double c = 0.5 * (o.image_size - 1);
  const Pose part_T_camera = look_at(centre + distance * direction, centre);
  Rasterizer r(cv::Size(o.image_size, o.image_size), f, f, c, c, part_T_camera);
  r.clear({0, 0, 0}, {0, 0, 0});
  r.draw(silhouette, Pose::Identity());
  const cv::Mat& depth = r.depth();
  cv::Mat mask = depth < 1e9f;
  std::vector<std::vector<cv::Point>> contours;
  cv::findContours(mask.clone(), contours, cv::RETR_EXTERNAL, cv::CHAIN_APPROX_NONE);
  ContourView view;
  view.direction = direction.cast<float>();
  size_t total = 0;
  for (const auto& ct : contours) total += ct.size();
  if (total == 0) return view;
  const double spacing = static_cast<double>(total) / o.points;
  const Eigen::Matrix3d R = part_T_camera.linear();
  const int max_run = o.image_size / 2;
  double next = 0.5 * spacing;
  size_t offset = 0;
  for (const auto& ct : contours) {
    const int n = static_cast<int>(ct.size());
    for (; next < offset + ct.size(); next += spacing) {
      const int i = static_cast<int>(next - offset);
      if (n < 7) continue;
      const cv::Point a = ct[(i + n - 3) % n], b = ct[(i + 3) % n], p = ct[i];
      Eigen::Vector2d normal(b.y - a.y, -(b.x - a.x));
      if (normal.norm() < 1e-9) continue;
      normal.normalize();
      // Outward is where the mask ends: test two pixels away on both sides.
      const Eigen::Vector2d pp(p.x, p.y);
      auto inside_at = [&](const Eigen::Vector2d& q) {
        const int x = static_cast<int>(std::lround(q.x())), y = static_cast<int>(std::lround(q.y()));
        return x >= 0 && y >= 0 && x < mask.cols && y < mask.rows && mask.at<uchar>(y, x) != 0;
      };
      if (inside_at(pp + 2 * normal) && !inside_at(pp - 2 * normal)) normal = -normal;
      const float z = depth.at<float>(p.y, p.x);
      // The silhouette's edge lies half a pixel outside the centre of its last pixel.
      const Eigen::Vector2d edge = pp + 0.5 * normal;
      const Eigen::Vector3d in_camera((edge.x() - c) * z / f, (edge.y() - c) * z / f, z);
      ContourPoint cp;
      cp.position = (part_T_camera * in_camera).cast<float>();
      cp.normal = (R * Eigen::Vector3d(normal.x(), normal.y(), 0.0)).cast<float>();
      const double metres_per_px = z / f;
      cp.inner = static_cast<float>((run_length(mask, pp, -normal, true, max_run) + 1) * metres_per_px);
      cp.outer = static_cast<float>((run_length(mask, pp, normal, false, max_run)) * metres_per_px);
      view.points.push_back(cp);
    }
    offset += ct.size();
  }
  return view;
}

}  // namespace

std::vector<Eigen::Vector3d> sphere_directions(int n) {
  std::vector<Eigen::Vector3d> out;
  out.reserve(n);
  const double golden = M_PI * (3.0 - std::sqrt(5.0));
  for (int i = 0; i < n; ++i) {
    const double z = 1.0 - (2.0 * i + 1.0) / n;
    const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
    out.emplace_back(r * std::cos(golden * i), r * std::sin(golden * i), z);
  }
  return out;
}

ContourModel::ContourModel(const RenderMesh& mesh, const ContourModelOptions& o) {
  if (mesh.vertices.empty() || mesh.triangles.empty()) throw std::invalid_argument("ContourModel: empty mesh");
  const Eigen::AlignedBox3f box = mesh.bounds();
  centre_ = box.center().cast<double>();
  for (const auto& v : mesh.vertices) radius_ = std::max(radius_, (v.cast<double>() - centre_).norm());
  const RenderMesh silhouette = mesh.geometry();
  for (const auto& d : sphere_directions(o.views)) views_.push_back(render_view(silhouette, d, centre_, radius_, o));
  index_views();
}

ContourModel::ContourModel(std::vector<ContourView> views, const Eigen::Vector3d& centre, double radius)
    : views_(std::move(views)), centre_(centre), radius_(radius) {
  index_views();
}

namespace {

constexpr int kCellsPerEdge = 8;  // of each face of the cube: 384 cells of about 11 degrees

// The cube face a direction passes through (0-5) and where on it, in [-1, 1] squared.
int cube_face(const Eigen::Vector3d& d, Eigen::Vector2d& at) {
  int axis = 0;
  d.cwiseAbs().maxCoeff(&axis);
  const int b = (axis + 1) % 3, c = (axis + 2) % 3;
  at = Eigen::Vector2d(d[b], d[c]) / std::abs(d[axis]);
  return 2 * axis + (d[axis] < 0 ? 1 : 0);
}

Eigen::Vector3d on_cube(int face, const Eigen::Vector2d& at) {
  const int axis = face / 2, b = (axis + 1) % 3, c = (axis + 2) % 3;
  Eigen::Vector3d p;
  p[axis] = face % 2 ? -1.0 : 1.0;
  p[b] = at.x(), p[c] = at.y();
  return p.normalized();
}

int cell_of(int face, const Eigen::Vector2d& at) {
  auto index = [](double x) { return std::clamp(static_cast<int>((x + 1) / 2 * kCellsPerEdge), 0, kCellsPerEdge - 1); };
  return (face * kCellsPerEdge + index(at.y())) * kCellsPerEdge + index(at.x());
}

}  // namespace

void ContourModel::index_views() {
  // A view can be nearest to a direction d of a cell (at most r from the cell's centre c) only
  // if it lies within (nearest to c) + 2r of c: the nearest to d is no farther from d than the
  // one nearest to c, which is within (nearest to c) + r of d. The slack covers the float dots.
  constexpr double kSlack = 0.01;  // rad
  cell_views_.assign(6 * kCellsPerEdge * kCellsPerEdge, {});
  std::vector<Eigen::Vector3d> directions;
  for (const auto& v : views_) directions.push_back(v.direction.cast<double>().normalized());
  std::vector<double> angles(views_.size());
  const double cell = 2.0 / kCellsPerEdge;
  for (int face = 0; face < 6; ++face)
    for (int j = 0; j < kCellsPerEdge; ++j)
      for (int i = 0; i < kCellsPerEdge; ++i) {
        const Eigen::Vector2d low(-1 + i * cell, -1 + j * cell);
        const Eigen::Vector3d c = on_cube(face, low + Eigen::Vector2d::Constant(cell / 2));
        // The cell is the cone over a square; the cone of directions within an angle of c is
        // convex, so the farthest direction of the cell is a corner.
        double r = 0.0;
        for (const auto& corner : {low, Eigen::Vector2d(low.x() + cell, low.y()), Eigen::Vector2d(low.x(), low.y() + cell),
                                   Eigen::Vector2d(low.x() + cell, low.y() + cell)})
          r = std::max(r, std::acos(std::clamp(c.dot(on_cube(face, corner)), -1.0, 1.0)));
        double nearest = M_PI;
        for (size_t v = 0; v < views_.size(); ++v) {
          angles[v] = std::acos(std::clamp(c.dot(directions[v]), -1.0, 1.0));
          nearest = std::min(nearest, angles[v]);
        }
        std::vector<int>& in_cell = cell_views_[(face * kCellsPerEdge + j) * kCellsPerEdge + i];
        for (size_t v = 0; v < views_.size(); ++v)
          if (angles[v] <= nearest + 2 * r + kSlack) in_cell.push_back(static_cast<int>(v));
      }
}

const ContourView& ContourModel::nearest_view(const Eigen::Vector3d& towards_camera) const {
  if (!(towards_camera.cwiseAbs().maxCoeff() > 0.0) || !towards_camera.allFinite()) return views_.front();
  const Eigen::Vector3f d = towards_camera.normalized().cast<float>();
  Eigen::Vector2d at;
  const int face = cube_face(towards_camera, at);
  size_t best = 0;
  float best_dot = -2.f;
  for (const int i : cell_views_[cell_of(face, at)]) {
    const float dot = views_[i].direction.dot(d);
    if (dot > best_dot) best_dot = dot, best = static_cast<size_t>(i);
  }
  return views_[best];
}

}  // namespace demoplan::perception
