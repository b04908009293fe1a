#pragma once
// A part's silhouette seen from many directions, computed once from its mesh (the sparse
// viewpoint model of SRT3D, Stoiber et al. 2022): for each direction of a near-uniform set on the
// sphere, points on the silhouette's contour with their outward normals, in the part's frame. A
// region-based tracker projects the view nearest to its current estimate instead of rendering
// the mesh every frame.
#include <vector>

#include <Eigen/Core>

#include "core/geometry/se3.h"
#include "perception/render/render_mesh.h"

namespace demoplan::perception {

struct ContourPoint {
  Eigen::Vector3f position;  // on the surface, part frame (m)
  Eigen::Vector3f normal;    // outward in the image plane of the view, part frame (unit)
  float inner = 0.f;         // how far the silhouette continues inward along -normal (m)
  float outer = 0.f;         // how far it is free outward along +normal (m; capped)
};

struct ContourView {
  Eigen::Vector3f direction;  // from the part's centre towards the camera, part frame (unit)
  std::vector<ContourPoint> points;
};

struct ContourModelOptions {
  int views = 642;          // directions on the sphere
  int points = 200;         // contour points per view
  int image_size = 200;     // px of the rendered silhouettes (the part fills about 85 %)
};

class ContourModel {
public:
  explicit ContourModel(const RenderMesh& mesh, const ContourModelOptions& options = {});
  // A model from its parts (as read back from a file, contour_model_file.h).
  ContourModel(std::vector<ContourView> views, const Eigen::Vector3d& centre, double radius);

  // The view whose direction is nearest to `towards_camera` (part frame, need not be unit; of
  // equally near ones the first).
  const ContourView& nearest_view(const Eigen::Vector3d& towards_camera) const;
  // The view nearest to where the camera is seen from the part posed at `camera_T_part`.
  const ContourView& view_from(const Pose& camera_T_part) const {
    return nearest_view(-(camera_T_part.linear().transpose() * camera_T_part.translation()) - centre_);
  }
  const std::vector<ContourView>& views() const { return views_; }
  const Eigen::Vector3d& centre() const { return centre_; }  // of the mesh's bounding box
  double radius() const { return radius_; }                   // bounding sphere about centre()

private:
  void index_views();

  std::vector<ContourView> views_;
  // Per cell of a cube around the sphere of directions, the views that can be nearest to a
  // direction in it, in order: nearest_view looks at a few views instead of all (same answer).
  std::vector<std::vector<int>> cell_views_;
  Eigen::Vector3d centre_;
  double radius_ = 0.0;
};

// `n` near-uniform unit directions (a Fibonacci sphere).
std::vector<Eigen::Vector3d> sphere_directions(int n);

}  // namespace demoplan::perception
