#pragma once
// A conservative pre-test for robot self pairs that one or two revolute joints move apart
// (the Panda's forearm against its flange and hand, moved by joints 6 and 7): these sit within
// millimetres of each other in most configurations, where no sphere bound separates them, and
// they made most of the FCL calls the sphere test left.
//
// The pair's exact distance (FCL) is sampled on a grid over those joints, each node measured
// the first time a query lands near it. A configuration is certainly free for the pair when
// the distance at its nearest node exceeds how far any point of the moving body can travel
// between the node and the configuration: per joint, the angle difference times the body's
// farthest reach from that joint's origin. Like the sphere test it answers only "certainly
// free"; otherwise FCL's narrow phase decides, so answers stay FCL's.
//
// The table belongs to one checker and is shared by its threads: nodes are atomics written
// once (two threads measuring the same node write the same value).
#include <Eigen/Core>
#include <atomic>
#include <memory>

#include "core/geometry/se3.h"
#include "core/model/robot_model.h"
#include "core/scene/geometry_bounds.h"
#include "core/scene/fcl_forward.h"

namespace demoplan {

// One side of a self pair: a geometry on a robot link.
struct LinkGeometry {
  int link = -1;
  Pose local = Pose::Identity();  // in the link frame
  std::shared_ptr<const fcl::CollisionObject<double>> prototype;  // at the identity
  const GeometryBound* bound = nullptr;  // its bounding sphere gives the body's reach
};

class JointPairTable {
public:
  // Null unless one link is an ancestor of the other and the links between them are moved by
  // one or two revolute joints with finite limits (no mimic joints, no prismatic ones).
  static std::unique_ptr<JointPairTable> make(const RobotModel& model, const LinkGeometry& a,
                                              const LinkGeometry& b);
  ~JointPairTable();

  // True only when FCL would find the pair free at q (the full configuration vector).
  bool certainly_free(const Eigen::VectorXd& q) const;

  int joint_count() const { return n_; }
  std::size_t node_count() const { return nodes_; }
  std::size_t nodes_measured() const;

  // Grid spacing: the nearest node is at most this far (metres of travel) from any query.
  // Finer grids prove more but fill more slowly: on random Panda configurations 4 mm gave
  // 2.62x FCL alone once filled but a first pass 1.5x slower than FCL; 16 mm 2.71x and a first
  // pass about as fast as FCL; 32 mm 2.42x (bench_collision, docs/benchmarks.md).
  static constexpr double kNodeTravel = 0.016;
  static constexpr int kMaxNodesPerJoint = 512;

private:
  JointPairTable() = default;
  float measure(const double* node_values) const;  // FCL distance, rounded down; -1 in contact

  LinkGeometry ancestor_, moving_;
  int n_ = 0;                       // moving joints on the chain, 1 or 2
  int q_index_[2] = {-1, -1};       // their configuration slots, ancestor side first
  double lower_[2] = {0, 0}, step_[2] = {1, 1};
  int count_[2] = {1, 1};
  double reach_[2] = {0, 0};        // farthest point of the moving body from each joint's origin
  // The chain from the ancestor link to the moving link: fixed transforms between the moving
  // joints: before_[0] up to joint 0's motion, before_[1] from there up to joint 1's, after_ the rest.
  Pose before_[2] = {Pose::Identity(), Pose::Identity()};
  Pose after_ = Pose::Identity();
  Eigen::Vector3d axis_[2] = {Eigen::Vector3d::UnitZ(), Eigen::Vector3d::UnitZ()};
  std::size_t nodes_ = 0;
  std::unique_ptr<std::atomic<float>[]> distance_;  // NaN until measured
};

}  // namespace demoplan
