#pragma once
// Where a lost part may have come to rest: standing on a support of the furniture (a table's
// top, a shelf's board) as it stood at its last rest or laid on a side, turned about the
// vertical. A carried part that the tracker lost is put down somewhere, often half behind
// furniture; a search among the poses where it could physically rest has three degrees of
// freedom (across the support and the turn) instead of six, and its depth comes from the
// support rather than from the silhouette's size. The world's z points up (as in the tasks and
// cells).
#include <array>
#include <optional>
#include <vector>

#include <Eigen/Geometry>
#include <opencv2/core.hpp>

#include "core/geometry/se3.h"
#include "perception/render/part_meshes.h"
#include "perception/tracking/color_histograms.h"
#include "perception/tracking/contour_model.h"
#include "perception/tracking/region_pose.h"

namespace demoplan::perception {

// The furniture's upward faces, grouped by height.
struct SupportLevel {
  double height = 0.0;  // m, world z
  std::vector<std::array<Eigen::Vector2d, 3>> triangles;  // world x, y
  Eigen::AlignedBox2d bounds;
  bool holds(const Eigen::Vector2d& xy) const;  // (x, y) lies over one of its triangles
};

// Faces within `max_tilt` (rad) of horizontal, facing up; faces within `merge` m of height share
// a level. Faces smaller than `min_area` m^2 are left out (a bevel is no support).
std::vector<SupportLevel> support_levels(const std::vector<FurnitureMesh>& furniture, double max_tilt = 0.05,
                                         double merge = 0.003, double min_area = 1e-4);

// A part's top (carrier_top.h: a polygon in the world, nearly level) as a support level at its
// mean height: a part put down on a tray, or on another part, rests there.
SupportLevel support_level(const std::vector<Eigen::Vector3d>& polygon);

// How far the centre of a mesh stands above its lowest point at that orientation (world z).
double centre_height(const RenderMesh& mesh, const Eigen::Vector3d& centre, const Eigen::Matrix3d& world_R_part);

// The height (world z) of a mesh's lowest point at `world_T_part`.
double lowest_point_height(const RenderMesh& mesh, const Pose& world_T_part);

// Whether `world_point` lies inside one of the furniture's boxes (the visuals that are boxes:
// walls, boards, table tops; other meshes may be hollow, a shelf's inside, and are not asked).
bool inside_furniture_box(const std::vector<FurnitureMesh>& furniture, const Eigen::Vector3d& world_point);

// A part as it would rest: its bounding box (part frame), the box's centre, and that centre's
// height above the part's lowest point at the rest's orientation (centre_height).
struct RestingPart {
  Eigen::AlignedBox3d box;
  double lift = 0.0;
};

// The pose of a part resting on a support at `height` at orientation `world_R_rest` turned about
// the vertical by `turn` (rad), its centre's image at `pixel`: the point of the pixel's ray at
// the centre's resting height. Empty when that point is behind the camera.
std::optional<Pose> resting_pose(double height, const RestingPart& part, const Eigen::Matrix3d& world_R_rest, double turn,
                                 const Pose& world_T_camera, const PinholeIntrinsics& camera, const Eigen::Vector2d& pixel);

struct RestingCandidate {
  Pose camera_T_part;
  Eigen::Vector2d pixel;  // of its centre
  double turn = 0.0;
  size_t level = 0;
  size_t face = 0;  // which of the orientations searched it rests at
};

// Whether a part at `world_T_part` stands on one of `levels`: its lowest point within
// `height_tolerance` (m) of the level's height, its centre over the level, its axis nearest up
// within `max_tilt` (rad) of the vertical.
bool stands_on(const std::vector<SupportLevel>& levels, const RenderMesh& mesh, const Eigen::Vector3d& centre,
               const Pose& world_T_part, double height_tolerance, double max_tilt);

// How far a part at `world_T_part` floats: its lowest point above the highest of `levels` under
// its `centre` (part frame) that it is not sunk into by more than `height_tolerance` (m);
// infinity over none.
double height_above_levels(const std::vector<SupportLevel>& levels, const RenderMesh& mesh, const Eigen::Vector3d& centre,
                           const Pose& world_T_part, double height_tolerance);

// The orientations of a part laid on each side of its box (a box put down on its side, not as
// it stood at `last_rest`): the part's axes +-x, +-y, +-z turned onto the world's down, those
// within 45 degrees of the last rest's down or up axis left out (a part is seldom put down
// upside down).
std::vector<Eigen::Matrix3d> laid_on_sides(const Eigen::Matrix3d& last_rest);

// The orientation nearest `world_R` that stands on a flat support: the part's axis nearest the
// world's down turned onto it by the smallest rotation (a tracked rest is a few degrees off
// level; the part stood level).
Eigen::Matrix3d standing_level(const Eigen::Matrix3d& world_R);

// The resting poses for each of `pixels` (image coordinates), level and turn (resting_pose) that
// the level holds and whose core (the part's box shrunk to half about its centre) is in no
// furniture box: a part cannot rest inside a wall.
std::vector<RestingCandidate> resting_candidates(const std::vector<SupportLevel>& levels, const RestingPart& part,
                                                 const Eigen::Matrix3d& world_R_rest, const std::vector<double>& turns,
                                                 const Pose& world_T_camera, const PinholeIntrinsics& camera,
                                                 const std::vector<Eigen::Vector2d>& pixels,
                                                 const std::vector<FurnitureMesh>& furniture = {});

// contour_contrast over the lines something else leaves visible: a line whose inner samples
// the occlusion map covers (furniture, another part nearer) is not counted. `visible`: the lines
// counted, of `lines` tried (every `stride`-th contour point).
struct VisibleContrast {
  double contrast = 0.0;
  int lines = 0, visible = 0;
};
VisibleContrast visible_contrast(const cv::Mat& image, const PinholeIntrinsics& camera, const ContourModel& model,
                                 const ColorHistograms& colors, const Pose& camera_T_part, const OcclusionMap& occlusion,
                                 int part, int samples = 4, int step = 2, int stride = 2);

}  // namespace demoplan::perception
