#include "perception/render/render_mesh.h"

#include <cmath>

#include <opencv2/imgcodecs.hpp>

#include "core/error.h"

namespace demoplan::perception {

Eigen::AlignedBox3f RenderMesh::bounds() const {
  Eigen::AlignedBox3f box;
  for (const auto& v : vertices) box.extend(v);
  return box;
}

RenderMesh RenderMesh::geometry() const {
  RenderMesh out;
  out.vertices = vertices;
  out.triangles = triangles;
  out.color = color;
  return out;
}

void RenderMesh::append(const RenderMesh& other, const Pose& transform) {
  const auto base = static_cast<std::uint32_t>(vertices.size());
  const Eigen::Affine3f T = transform.cast<float>();
  for (const auto& v : other.vertices) vertices.push_back(T * v);
  for (const auto& t : other.triangles) triangles.push_back({t[0] + base, t[1] + base, t[2] + base});
  uvs.clear();  // a merged mesh is drawn in one colour
}

RenderMesh render_mesh(const TriangleMesh& mesh, const Eigen::Vector3d& scale, const Pose& origin, TextureUse texture) {
  RenderMesh out;
  const Eigen::Affine3f T = origin.cast<float>();
  const Eigen::Vector3f s = scale.cast<float>();
  out.vertices.reserve(mesh.vertices.size());
  for (const auto& v : mesh.vertices) out.vertices.push_back(T * Eigen::Vector3f(v.cwiseProduct(s)));
  out.triangles = mesh.triangles;
  out.color = {mesh.color[2] * 255.f, mesh.color[1] * 255.f, mesh.color[0] * 255.f};
  if (texture == TextureUse::Load && !mesh.texture_path.empty() && mesh.uvs.size() == mesh.vertices.size()) {
    out.texture = cv::imread(mesh.texture_path, cv::IMREAD_COLOR);
    if (out.texture.empty()) throw InputError(mesh.texture_path, "", "cannot read the texture image");
    out.uvs = mesh.uvs;
  }
  return out;
}

RenderMesh box_mesh(const Eigen::Vector3d& size, const cv::Vec3f& bgr) {
  RenderMesh m;
  m.color = bgr;
  const Eigen::Vector3f h = (size / 2).cast<float>();
  for (int i = 0; i < 8; ++i)
    m.vertices.emplace_back(i & 1 ? h.x() : -h.x(), i & 2 ? h.y() : -h.y(), i & 4 ? h.z() : -h.z());
  // Two triangles per face, counter-clockwise seen from outside.
  const int faces[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (const auto& f : faces) {
    m.triangles.push_back({std::uint32_t(f[0]), std::uint32_t(f[1]), std::uint32_t(f[2])});
    m.triangles.push_back({std::uint32_t(f[0]), std::uint32_t(f[2]), std::uint32_t(f[3])});
  }
  return m;
}

RenderMesh cylinder_mesh(double radius, double length, const cv::Vec3f& bgr, int segments) {
  RenderMesh m;
  m.color = bgr;
  const float r = static_cast<float>(radius), h = static_cast<float>(length / 2);
  for (int i = 0; i < segments; ++i) {
    const float a = static_cast<float>(2 * M_PI * i / segments);
    m.vertices.emplace_back(r * std::cos(a), r * std::sin(a), -h);
    m.vertices.emplace_back(r * std::cos(a), r * std::sin(a), h);
  }
  const auto bottom = static_cast<std::uint32_t>(m.vertices.size());
  m.vertices.emplace_back(0.f, 0.f, -h);
  m.vertices.emplace_back(0.f, 0.f, h);
  for (int i = 0; i < segments; ++i) {
    const auto a = static_cast<std::uint32_t>(2 * i), b = static_cast<std::uint32_t>(2 * ((i + 1) % segments));
    m.triangles.push_back({a, b, b + 1});
    m.triangles.push_back({a, b + 1, a + 1});
    m.triangles.push_back({bottom, b, a});
    m.triangles.push_back({bottom + 1, a + 1, b + 1});
  }
  return m;
}

}  // namespace demoplan::perception
