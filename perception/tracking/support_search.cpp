#include "perception/tracking/support_search.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/geometry/polygon_2d.h"

namespace demoplan::perception {

bool SupportLevel::holds(const Eigen::Vector2d& xy) const {
  if (!bounds.contains(xy)) return false;
  for (const auto& t : triangles) {
    const double a = cross2(t[1] - t[0], xy - t[0]), b = cross2(t[2] - t[1], xy - t[1]), c = cross2(t[0] - t[2], xy - t[2]);
    if ((a >= 0 && b >= 0 && c >= 0) || (a <= 0 && b <= 0 && c <= 0)) return true;
  }
  return false;
}

std::vector<SupportLevel> support_levels(const std::vector<FurnitureMesh>& furniture, double max_tilt, double merge,
                                         double min_area) {
  std::vector<SupportLevel> levels;
  const double min_up = std::cos(max_tilt);
  for (const auto& f : furniture)
    for (const auto& tri : f.mesh.triangles) {
      Eigen::Vector3d v[3];
      for (int i = 0; i < 3; ++i) v[i] = f.world_T_mesh * f.mesh.vertices[tri[i]].cast<double>();
      const Eigen::Vector3d n = (v[1] - v[0]).cross(v[2] - v[0]);
      const double area = 0.5 * n.norm();
      // Facing up (counter-clockwise seen from outside, as the renderer's meshes): a face seen
      // from below, a table's underside, holds nothing.
      if (area < min_area || n.z() < min_up * n.norm()) continue;
      const double height = (v[0].z() + v[1].z() + v[2].z()) / 3;
      auto level = std::find_if(levels.begin(), levels.end(),
                                [&](const SupportLevel& l) { return std::abs(l.height - height) < merge; });
      if (level == levels.end()) {
        levels.push_back({height, {}, Eigen::AlignedBox2d()});
        level = levels.end() - 1;
      }
      level->triangles.push_back({v[0].head<2>(), v[1].head<2>(), v[2].head<2>()});
      for (const auto& p : v) level->bounds.extend(p.head<2>());
    }
  return levels;
}

SupportLevel support_level(const std::vector<Eigen::Vector3d>& polygon) {
  SupportLevel level;
  for (const auto& v : polygon) level.height += v.z() / static_cast<double>(polygon.size());
  for (size_t i = 1; i + 1 < polygon.size(); ++i)
    level.triangles.push_back({polygon[0].head<2>(), polygon[i].head<2>(), polygon[i + 1].head<2>()});
  for (const auto& v : polygon) level.bounds.extend(v.head<2>());
  return level;
}

bool stands_on(const std::vector<SupportLevel>& levels, const RenderMesh& mesh, const Eigen::Vector3d& centre,
               const Pose& world_T_part, double height_tolerance, double max_tilt) {
  const Eigen::Matrix3d& R = world_T_part.linear();
  if (R.row(2).cwiseAbs().maxCoeff() < std::cos(max_tilt)) return false;  // its axis nearest up
  const Eigen::Vector3d at = world_T_part * centre;
  const double bottom = lowest_point_height(mesh, world_T_part);
  return std::any_of(levels.begin(), levels.end(), [&](const SupportLevel& l) {
    return std::abs(bottom - l.height) <= height_tolerance && l.holds(at.head<2>());
  });
}

double height_above_levels(const std::vector<SupportLevel>& levels, const RenderMesh& mesh, const Eigen::Vector3d& centre,
                           const Pose& world_T_part, double height_tolerance) {
  const Eigen::Vector2d at = (world_T_part * centre).head<2>();
  const double bottom = lowest_point_height(mesh, world_T_part);
  double above = std::numeric_limits<double>::infinity();
  for (const SupportLevel& l : levels)
    if (l.holds(at) && bottom - l.height > -height_tolerance) above = std::min(above, bottom - l.height);
  return above;
}

namespace {

// The least of the mesh's vertices along `up` (part frame).
double lowest_along(const RenderMesh& mesh, const Eigen::Vector3d& up) {
  double lowest = std::numeric_limits<double>::max();
  for (const auto& v : mesh.vertices) lowest = std::min(lowest, up.dot(v.cast<double>()));
  return lowest;
}

}  // namespace

double lowest_point_height(const RenderMesh& mesh, const Pose& world_T_part) {
  // The vertical in the part's frame.
  return world_T_part.translation().z() + lowest_along(mesh, world_T_part.linear().transpose().col(2));
}

double centre_height(const RenderMesh& mesh, const Eigen::Vector3d& centre, const Eigen::Matrix3d& world_R_part) {
  const Eigen::Vector3d up = world_R_part.transpose().col(2);  // the vertical in the part's frame
  return up.dot(centre) - lowest_along(mesh, up);
}

bool inside_furniture_box(const std::vector<FurnitureMesh>& furniture, const Eigen::Vector3d& world_point) {
  for (const auto& f : furniture) {
    if (!f.box) continue;
    const Eigen::Vector3d p = f.world_T_mesh.linear().transpose() * (world_point - f.world_T_mesh.translation());
    if ((p.cwiseAbs() - *f.box / 2).maxCoeff() < 0) return true;
  }
  return false;
}

std::optional<Pose> resting_pose(double height, const RestingPart& part, const Eigen::Matrix3d& world_R_rest, double turn,
                                 const Pose& world_T_camera, const PinholeIntrinsics& K, const Eigen::Vector2d& pixel) {
  const Eigen::Vector3d eye = world_T_camera.translation();
  const Eigen::Vector3d ray = world_T_camera.linear() * Eigen::Vector3d((pixel.x() - K.cx) / K.fx, (pixel.y() - K.cy) / K.fy, 1.0);
  if (std::abs(ray.z()) < 1e-9) return std::nullopt;
  const double t = (height + part.lift - eye.z()) / ray.z();
  if (t <= 0.05) return std::nullopt;  // that height is behind the camera along this ray
  Pose world_T_part = Pose::Identity();
  world_T_part.linear() = Eigen::AngleAxisd(turn, Eigen::Vector3d::UnitZ()).toRotationMatrix() * world_R_rest;
  world_T_part.translation() = eye + t * ray - world_T_part.linear() * part.box.center();
  return world_T_camera.inverse() * world_T_part;
}

std::vector<Eigen::Matrix3d> laid_on_sides(const Eigen::Matrix3d& last_rest) {
  std::vector<Eigen::Matrix3d> out;
  const Eigen::Vector3d down_before = last_rest.transpose() * -Eigen::Vector3d::UnitZ();  // part frame
  for (int axis = 0; axis < 3; ++axis)
    for (const double sign : {1.0, -1.0}) {
      const Eigen::Vector3d down = sign * Eigen::Vector3d::Unit(axis);
      if (std::abs(down.dot(down_before)) > std::cos(M_PI / 4)) continue;  // as it stood, or upside down
      out.push_back(Eigen::Quaterniond::FromTwoVectors(down, -Eigen::Vector3d::UnitZ()).toRotationMatrix());
    }
  return out;
}

Eigen::Matrix3d standing_level(const Eigen::Matrix3d& world_R) {
  const Eigen::Vector3d nearest = -axis_nearest_up(world_R);  // the axis nearest down (part frame)
  return Eigen::Quaterniond::FromTwoVectors(world_R * nearest, -Eigen::Vector3d::UnitZ()).toRotationMatrix() * world_R;
}

std::vector<RestingCandidate> resting_candidates(const std::vector<SupportLevel>& levels, const RestingPart& part,
                                                 const Eigen::Matrix3d& world_R_rest, const std::vector<double>& turns,
                                                 const Pose& world_T_camera, const PinholeIntrinsics& K,
                                                 const std::vector<Eigen::Vector2d>& pixels,
                                                 const std::vector<FurnitureMesh>& furniture) {
  std::vector<RestingCandidate> out;
  const Eigen::Vector3d centre = part.box.center();
  // The core's corners about the centre (part frame).
  std::vector<Eigen::Vector3d> core{Eigen::Vector3d::Zero()};
  for (int i = 0; i < 8; ++i) core.push_back(0.5 * (part.box.corner(static_cast<Eigen::AlignedBox3d::CornerType>(i)) - centre));
  for (const auto& u : pixels)
    for (size_t l = 0; l < levels.size(); ++l)
      for (const double turn : turns) {
        const std::optional<Pose> camera_T_part = resting_pose(levels[l].height, part, world_R_rest, turn, world_T_camera, K, u);
        if (!camera_T_part) break;
        const Pose world_T_part = world_T_camera * *camera_T_part;
        const Eigen::Vector3d at = world_T_part * centre;
        if (!levels[l].holds(at.head<2>())) break;
        const bool blocked = std::any_of(core.begin(), core.end(), [&](const Eigen::Vector3d& c) {
          return inside_furniture_box(furniture, at + world_T_part.linear() * c);
        });
        if (!blocked) out.push_back({*camera_T_part, u, turn, l});
      }
  return out;
}

VisibleContrast visible_contrast(const cv::Mat& image, const PinholeIntrinsics& K, const ContourModel& model,
                                 const ColorHistograms& colors, const Pose& T, const OcclusionMap& occlusion, int part,
                                 int samples, int step, int stride) {
  VisibleContrast result;
  const ContourView& view = model.view_from(T);
  double sum = 0.0;
  auto inside = [&](const Eigen::Vector2d& q) { return q.x() >= 0 && q.y() >= 0 && q.x() < image.cols - 0.5 && q.y() < image.rows - 0.5; };
  for (size_t j = 0; j < view.points.size(); j += std::max(stride, 1)) {
    ++result.lines;
    const Eigen::Vector3d X = T * view.points[j].position.cast<double>();
    if (X.z() < 0.05) continue;
    const Eigen::Vector2d pixel(K.fx * X.x() / X.z() + K.cx, K.fy * X.y() / X.z() + K.cy);
    const Eigen::Vector3d n = T.linear() * view.points[j].normal.cast<double>();
    const Eigen::Vector2d d(K.fx * (n.x() - X.x() / X.z() * n.z()), K.fy * (n.y() - X.y() / X.z() * n.z()));
    if (d.norm() < 1e-12) continue;
    const Eigen::Vector2d normal = d.normalized();
    double in = 0.0, out = 0.0;
    bool ok = true;
    for (int i = 0; i < samples && ok; ++i) {
      const Eigen::Vector2d a = pixel - (0.5 + i * step) * normal, b = pixel + (0.5 + i * step) * normal;
      ok = inside(a) && inside(b) && (occlusion.empty() || !occlusion.hides(a.x(), a.y(), part, static_cast<float>(X.z())));
      // Rounded to the nearest pixel (inside the image, so from 0 on: no need for lround's call).
      if (ok)
        in += colors.foreground_probability(image.at<cv::Vec3b>(static_cast<int>(a.y() + 0.5), static_cast<int>(a.x() + 0.5))),
            out += colors.foreground_probability(image.at<cv::Vec3b>(static_cast<int>(b.y() + 0.5), static_cast<int>(b.x() + 0.5)));
    }
    if (!ok) continue;
    sum += (in - out) / samples;
    ++result.visible;
  }
  result.contrast = result.visible ? sum / result.visible : 0.0;
  return result;
}

}  // namespace demoplan::perception
