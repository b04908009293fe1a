// The software renderer's depth-only drawing (occlusion maps) against its full drawing.
#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include "perception/render/rasterizer.h"
#include "perception/render/render_mesh.h"

namespace demoplan::perception {
namespace {

Pose at(double x, double y, double z, double turn = 0.0) {
  Pose T = Pose::Identity();
  T.linear() = Eigen::AngleAxisd(turn, Eigen::Vector3d(0.3, 1.0, 0.2).normalized()).toRotationMatrix();
  T.translation() << x, y, z;
  return T;
}

Rasterizer camera() {
  Rasterizer r(cv::Size(320, 240), 300, 300, 159.5, 119.5, Pose::Identity());
  r.clear({0, 0, 0}, {0, 0, 0});
  return r;
}

int differing(const cv::Mat& a, const cv::Mat& b) { return cv::countNonZero(a != b); }

TEST(Rasterizer, DepthOnlyDrawingGivesTheSameDepthAsDrawing) {
  const RenderMesh box = box_mesh({0.2, 0.1, 0.3}, {50, 100, 150});
  const RenderMesh cylinder = cylinder_mesh(0.05, 0.4, {10, 20, 30}, 24);
  // A box in front of a turned cylinder, and a box the near plane (5 cm) cuts through.
  const std::vector<std::pair<const RenderMesh*, Pose>> scene = {
      {&cylinder, at(0.02, 0.01, 1.0, 0.7)}, {&box, at(-0.05, 0.0, 0.8, 0.4)}, {&box, at(0.1, 0.05, 0.08, 0.2)}};
  Rasterizer full = camera(), depth_only = camera();
  for (const auto& [mesh, pose] : scene) {
    full.draw(*mesh, pose);
    depth_only.draw_depth(*mesh, pose);
  }
  EXPECT_GT(cv::countNonZero(full.depth() < 1e9f), 10000);
  EXPECT_EQ(differing(full.depth(), depth_only.depth()), 0);
}

TEST(Rasterizer, DepthOnlyDrawingLabelsWhereTheMeshComesNearest) {
  const RenderMesh box = box_mesh({0.2, 0.2, 0.2}, {50, 100, 150});
  Rasterizer r = camera();
  cv::Mat labels(r.depth().size(), CV_8U, cv::Scalar(0));
  r.draw_depth(box, at(0.0, 0.0, 1.0), &labels, 1);
  const cv::Mat before = r.depth().clone();
  // Half in front of the first box, half beside it; its far side behind the first box's face.
  r.draw_depth(box, at(0.1, 0.0, 0.95, 0.3), &labels, 2);
  const cv::Mat nearer = r.depth() < before;
  EXPECT_GT(cv::countNonZero(nearer), 1000);
  EXPECT_EQ(differing(labels == 2, nearer), 0);
  EXPECT_GT(cv::countNonZero(labels == 1), 1000);  // the first box where the second is behind it or beside it
  EXPECT_EQ(differing(labels == 0, r.depth() > 1e9f), 0);
}

}  // namespace
}  // namespace demoplan::perception
