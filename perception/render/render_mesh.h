#pragma once
// Triangle meshes ready for the software renderer: vertices in metres in the mesh's own frame,
// optional texture coordinates and texture, or one colour.
#include <array>
#include <cstdint>
#include <vector>

#include <Eigen/Core>
#include <opencv2/core.hpp>

#include "core/geometry/se3.h"
#include "core/model/mesh.h"

namespace demoplan::perception {

struct RenderMesh {
  std::vector<Eigen::Vector3f> vertices;
  std::vector<Eigen::Vector2f> uvs;  // per vertex (OBJ convention: v up); empty when untextured
  std::vector<std::array<std::uint32_t, 3>> triangles;
  cv::Mat texture;                   // 8-bit BGR; empty: `color`
  cv::Vec3f color{200, 200, 200};    // BGR, 0..255

  Eigen::AlignedBox3f bounds() const;
  // The same triangles without texture or coordinates: cheaper to draw where only coverage and
  // depth count (silhouettes, occlusion).
  RenderMesh geometry() const;
  void append(const RenderMesh& other, const Pose& transform);  // geometry only, colour kept
};

// Whether a mesh's texture image is read: Skip for coverage and depth only (outlines), where
// decoding a 2048x2048 texture would cost more than drawing the mesh.
enum class TextureUse { Load, Skip };

// A loaded mesh with its URDF scale and origin applied; the texture is read from its file.
// Throws InputError when the texture cannot be read.
RenderMesh render_mesh(const TriangleMesh& mesh, const Eigen::Vector3d& scale, const Pose& origin,
                       TextureUse texture = TextureUse::Load);

// Primitives, centred on their frame: a box of `size`, a cylinder along z.
RenderMesh box_mesh(const Eigen::Vector3d& size, const cv::Vec3f& bgr);
RenderMesh cylinder_mesh(double radius, double length, const cv::Vec3f& bgr, int segments = 16);

}  // namespace demoplan::perception
