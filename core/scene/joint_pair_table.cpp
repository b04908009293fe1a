#include "core/scene/joint_pair_table.h"

#include <fcl/fcl.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "core/model/kinematics.h"

namespace demoplan {

namespace {

// Joints from `top` down to `link`, in that order; empty when `top` is not above `link`.
std::vector<int> chain_below(const RobotModel& model, int top, int link) {
  std::vector<int> joints;
  for (int l = link; l != top; l = model.joints[model.links[l].parent_joint].parent_link) {
    if (model.links[l].parent_joint < 0) return {};
    joints.push_back(model.links[l].parent_joint);
  }
  std::reverse(joints.begin(), joints.end());
  return joints;
}

bool usable(const Joint& j) {
  return j.type == JointType::Revolute && !j.mimic && std::isfinite(j.limits.lower) &&
         std::isfinite(j.limits.upper) && j.limits.upper > j.limits.lower;
}

}  // namespace

JointPairTable::~JointPairTable() = default;

std::unique_ptr<JointPairTable> JointPairTable::make(const RobotModel& model, const LinkGeometry& a,
                                                     const LinkGeometry& b) {
  if (!a.prototype || !b.prototype || !a.bound || !b.bound || !b.bound->spheres || !a.bound->spheres)
    return nullptr;
  std::vector<int> chain = chain_below(model, a.link, b.link);
  const LinkGeometry* top = &a;
  const LinkGeometry* moving = &b;
  if (chain.empty()) {
    chain = chain_below(model, b.link, a.link);
    std::swap(top, moving);
  }
  if (chain.empty()) return nullptr;  // neither above the other (or the same link)

  std::unique_ptr<JointPairTable> t(new JointPairTable());
  t->ancestor_ = *top;
  t->moving_ = *moving;
  Pose fixed = Pose::Identity();  // the fixed transforms since the last moving joint
  for (int ji : chain) {
    const Joint& j = model.joints[ji];
    if (j.q_index < 0) {
      fixed = fixed * j.origin;
      continue;
    }
    if (!usable(j) || t->n_ == 2) return nullptr;
    const int k = t->n_++;
    t->before_[k] = fixed * j.origin;
    t->axis_[k] = j.axis;
    t->q_index_[k] = j.q_index;
    t->lower_[k] = j.limits.lower;
    fixed = Pose::Identity();
    // Count filled in below, once the reaches are known.
    t->step_[k] = j.limits.upper - j.limits.lower;
  }
  if (t->n_ == 0) return nullptr;
  t->after_ = fixed;

  // Reach of the moving body from the last joint's origin: its bounding sphere there; from the
  // joint before it, add the distance between the two joints' origins (rotation keeps lengths).
  const BoundingSphere& s = moving->bound->spheres->all;
  const int last = t->n_ - 1;
  t->reach_[last] = (t->after_ * moving->local * s.centre).norm() + s.radius;
  if (t->n_ == 2) t->reach_[0] = t->before_[1].translation().norm() + t->reach_[1];

  // Nodes close enough that the nearest one is at most kNodeTravel of travel away.
  for (int k = 0; k < t->n_; ++k) {
    const double range = t->step_[k];
    const double spacing = 2.0 * kNodeTravel / (t->n_ * std::max(t->reach_[k], 1e-6));
    t->count_[k] = std::clamp(static_cast<int>(std::ceil(range / spacing)) + 1, 2, kMaxNodesPerJoint);
    t->step_[k] = range / (t->count_[k] - 1);
  }
  t->nodes_ = static_cast<std::size_t>(t->count_[0]) * t->count_[1];
  t->distance_.reset(new std::atomic<float>[t->nodes_]);
  for (std::size_t i = 0; i < t->nodes_; ++i)
    t->distance_[i].store(std::numeric_limits<float>::quiet_NaN(), std::memory_order_relaxed);
  return t;
}

float JointPairTable::measure(const double* node_values) const {
  Pose T = Pose::Identity();
  for (int k = 0; k < n_; ++k) {
    T = T * before_[k];
    T.linear() = T.linear() * Eigen::AngleAxisd(node_values[k], axis_[k]).toRotationMatrix();
  }
  T = T * after_;
  fcl::CollisionObjectd a(*ancestor_.prototype), b(*moving_.prototype);
  a.setTransform(ancestor_.local);
  b.setTransform(T * moving_.local);
  a.computeAABB();
  b.computeAABB();
  fcl::CollisionRequestd creq;
  fcl::CollisionResultd cres;
  if (fcl::collide(&a, &b, creq, cres) > 0) return -1.0f;
  fcl::DistanceRequestd dreq;
  fcl::DistanceResultd dres;
  fcl::distance(&a, &b, dreq, dres);
  const double d = dres.min_distance;
  if (!(d > 0)) return -1.0f;
  float f = static_cast<float>(d);
  if (static_cast<double>(f) > d) f = std::nextafter(f, -std::numeric_limits<float>::infinity());
  return f;
}

bool JointPairTable::certainly_free(const Eigen::VectorXd& q) const {
  std::size_t index = 0;
  double travel = 0.0, node[2] = {0, 0};
  for (int k = 0; k < n_; ++k) {
    const double v = q[q_index_[k]];
    const int i = std::clamp(static_cast<int>(std::lround((v - lower_[k]) / step_[k])), 0, count_[k] - 1);
    node[k] = lower_[k] + i * step_[k];
    travel += std::abs(v - node[k]) * reach_[k];
    index = index * count_[k] + i;
  }
  float d = distance_[index].load(std::memory_order_relaxed);
  if (std::isnan(d)) {
    d = measure(node);
    distance_[index].store(d, std::memory_order_relaxed);
  }
  // The margin covers rounding in the kinematics and FCL's own tolerances (as the spheres' does).
  return d > travel + 1e-6;
}

std::size_t JointPairTable::nodes_measured() const {
  std::size_t n = 0;
  for (std::size_t i = 0; i < nodes_; ++i) n += !std::isnan(distance_[i].load(std::memory_order_relaxed));
  return n;
}

}  // namespace demoplan
