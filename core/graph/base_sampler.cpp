#include "core/graph/base_sampler.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <mutex>
#include <sstream>

#include "core/geometry/box_overlap.h"
#include "core/model/inverse_kinematics.h"
#include "core/model/kinematics.h"

namespace demoplan {

namespace {

// A box around a collision geometry, in the frame its pose is given in: exact for a box, the
// enclosing box of a cylinder, a sphere or a mesh's vertices.
bool bounding_box(const Geometry& g, const Pose& frame, Pose& pose, Eigen::Vector3d& half) {
  pose = frame * g.origin;
  if (const auto* b = std::get_if<BoxShape>(&g.shape)) {
    half = 0.5 * b->size;
  } else if (const auto* c = std::get_if<CylinderShape>(&g.shape)) {
    half = Eigen::Vector3d(c->radius, c->radius, 0.5 * c->length);
  } else if (const auto* s = std::get_if<SphereShape>(&g.shape)) {
    half = Eigen::Vector3d::Constant(s->radius);
  } else if (const auto* m = std::get_if<MeshShape>(&g.shape)) {
    if (!m->mesh || m->mesh->vertices.empty()) return false;
    Eigen::AlignedBox3d box;
    for (const auto& v : m->mesh->vertices) box.extend(v.cast<double>().cwiseProduct(m->scale));
    half = 0.5 * box.sizes();
    pose = pose * Eigen::Translation3d(box.center());
  }
  return true;
}

// The yaw about the vertical that best turns `from` onto `to` (least squares), and the angle left.
double best_yaw(const Eigen::Matrix3d& from, const Eigen::Matrix3d& to, double* residual) {
  const Eigen::Matrix3d M = to * from.transpose();
  const double yaw = std::atan2(M(1, 0) - M(0, 1), M(0, 0) + M(1, 1));
  *residual = log3(Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()).toRotationMatrix() * from * to.transpose()).norm();
  return yaw;
}

}  // namespace

// The reach map: the gripper frame relative to the body for random arm configurations, sorted
// by height. It depends on the robot, its gripper frame and the options only, so the samplers of
// one robot share one, built once per process (immutable, as the meshes' BVHs): the regrasp
// search makes a projector, and with it a sampler, for every placement it tries.
std::shared_ptr<const std::vector<BaseSampler::Reach>> BaseSampler::reach_map(const Scene& scene, const MobileBase& base,
                                                                              const std::vector<int>& arm,
                                                                              const BaseSamplerOptions& options) {
  const RobotModel& m = scene.robot.model;
  // Keyed by the model's address: a sampler holds its scene, so while a map is in use its model
  // lives and no other model can take that address.
  std::ostringstream key;
  key << std::hexfloat << &m << ' ' << base.body << ' ' << scene.robot.gripper_link << ' ' << options.seed << ' '
      << options.reach_samples;
  for (const int j : arm) key << ' ' << j;
  const Eigen::Matrix4d frame = scene.robot.gripper().pose.matrix();
  for (int k = 0; k < 16; ++k) key << ' ' << frame(k);
  static std::mutex mutex;
  static std::map<std::string, std::weak_ptr<const std::vector<Reach>>> cache;
  const std::lock_guard<std::mutex> lock(mutex);
  std::erase_if(cache, [](const auto& entry) { return entry.second.expired(); });
  std::weak_ptr<const std::vector<Reach>>& slot = cache[key.str()];
  if (auto shared = slot.lock()) return shared;

  IkProblem p;
  p.model = &m;
  p.root_link = base.body;
  p.link = scene.robot.gripper_link;
  p.link_T_frame = scene.robot.gripper().pose;
  const IkSolver fk(p);
  const Eigen::VectorXd lower = m.lower_limits(), upper = m.upper_limits();
  std::mt19937_64 rng(options.seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  Eigen::VectorXd q = Eigen::VectorXd::Zero(m.nq);
  auto reach = std::make_shared<std::vector<Reach>>();
  reach->reserve(static_cast<size_t>(options.reach_samples));
  for (int k = 0; k < options.reach_samples; ++k) {
    Reach r;
    r.arm.resize(static_cast<long>(arm.size()));
    for (size_t i = 0; i < arm.size(); ++i) {
      const int j = arm[i];
      const double lo = std::isfinite(lower[j]) ? lower[j] : -M_PI;
      const double hi = std::isfinite(upper[j]) ? upper[j] : M_PI;
      q[j] = r.arm[static_cast<long>(i)] = lo + u(rng) * (hi - lo);
    }
    r.gripper = fk.frame_pose(q);
    reach->push_back(std::move(r));
  }
  std::stable_sort(reach->begin(), reach->end(), [](const Reach& a, const Reach& b) {
    return a.gripper.translation().z() < b.gripper.translation().z();
  });
  slot = reach;
  return reach;
}

BaseSampler::BaseSampler(const Scene& scene, const MobileBase& base, std::vector<int> arm, BaseSamplerOptions options)
    : scene_(scene), base_(base), arm_(std::move(arm)), options_(options) {
  const RobotModel& m = scene.robot.model;
  lower_ = m.lower_limits();
  upper_ = m.upper_limits();

  reach_ = reach_map(scene, base_, arm_, options_);

  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(m.nq);
  body_height_ = base_.body_pose(m, zero, scene.robot.base).translation().z();
  // The robot's boxes, in their link frames, but for the hand and what hangs from it.
  std::vector<bool> hand(m.links.size(), false);
  for (size_t l = 0; l < m.links.size(); ++l) {
    const int pj = m.links[l].parent_joint;
    hand[l] = static_cast<int>(l) == scene.robot.gripper_link || (pj >= 0 && hand[static_cast<size_t>(m.joints[pj].parent_link)]);
  }
  for (size_t l = 0; l < m.links.size(); ++l) {
    if (hand[l]) continue;
    for (const Geometry& g : m.links[l].collisions) {
      Box b;
      b.link = static_cast<int>(l);
      if (bounding_box(g, Pose::Identity(), b.pose, b.half)) robot_.push_back(b);
    }
  }
  // The furniture's, in the world; links the robot never collides with are left out.
  for (const SceneFurniture& f : scene.furniture)
    for (size_t l = 0; l < f.model.links.size(); ++l) {
      const Link& link = f.model.links[l];
      if (std::find(f.robot_ignored_links.begin(), f.robot_ignored_links.end(), link.name) !=
          f.robot_ignored_links.end())
        continue;
      for (const Geometry& g : link.collisions) {
        Box b;
        if (bounding_box(g, f.link_poses[l], b.pose, b.half)) furniture_.push_back(b);
      }
    }
}

std::pair<size_t, size_t> BaseSampler::height_window(double z) const {
  auto below = [](const Reach& r, double h) { return r.gripper.translation().z() < h; };
  const auto lo = std::lower_bound(reach_->begin(), reach_->end(), z - options_.height_tolerance, below);
  const auto hi = std::lower_bound(reach_->begin(), reach_->end(), z + options_.height_tolerance, below);
  return {static_cast<size_t>(lo - reach_->begin()), static_cast<size_t>(hi - reach_->begin())};
}

bool BaseSampler::sample(const Pose& target, int link, Eigen::VectorXd& q, std::mt19937_64& rng) const {
  const RobotModel& m = scene_.robot.model;
  std::uniform_real_distribution<double> u(0.0, 1.0);
  auto uniform = [&](int j) { return lower_[j] + u(rng) * (upper_[j] - lower_[j]); };
  const bool on_body = link >= 0;
  Pose in_body = target;  // the target relative to the body when it rides on it
  if (on_body) {
    const std::vector<int> rigid = m.rigid_bodies();
    if (rigid[static_cast<size_t>(link)] != rigid[static_cast<size_t>(base_.body)]) return false;
    const Eigen::VectorXd zero = Eigen::VectorXd::Zero(m.nq);
    in_body = link_pose(m, zero, Pose::Identity(), base_.body).inverse() * link_pose(m, zero, Pose::Identity(), link) *
              target;
  }
  const auto [first, last] = height_window(on_body ? in_body.translation().z() : target.translation().z() - body_height_);
  if (first >= last) return false;
  std::uniform_int_distribution<size_t> pick(first, last - 1);
  // Of `candidates` reach samples clear of the furniture, the one whose gripper orientation is
  // closest to the handle's once turned about the vertical (on the deck: as it is).
  Eigen::VectorXd best = q, candidate = q;
  double best_error = std::numeric_limits<double>::infinity();
  int cleared = 0;
  for (int attempt = 0; attempt < options_.attempts * options_.candidates && cleared < options_.candidates; ++attempt) {
    const Reach& r = (*reach_)[pick(rng)];
    for (size_t i = 0; i < arm_.size(); ++i) candidate[arm_[i]] = r.arm[static_cast<long>(i)];
    double error = 0.0;
    if (on_body) {
      // The arm does not care where the base stands: anywhere the robot is clear.
      error = log3(r.gripper.linear().transpose() * in_body.linear()).norm();
      candidate[base_.x] = uniform(base_.x);
      candidate[base_.y] = uniform(base_.y);
      candidate[base_.yaw] = uniform(base_.yaw);
    } else {
      const double yaw = best_yaw(r.gripper.linear(), target.linear(), &error);
      const Eigen::Vector2d at =
          target.translation().head<2>() - Eigen::Rotation2Dd(yaw) * r.gripper.translation().head<2>();
      base_.set_body_pose(m, scene_.robot.base, at.x(), at.y(), yaw, candidate);
      bool inside = true;
      for (int j : {base_.x, base_.y, base_.yaw}) inside = inside && candidate[j] >= lower_[j] && candidate[j] <= upper_[j];
      if (!inside) continue;
    }
    if (!clear_of_furniture(candidate)) continue;
    ++cleared;
    if (error < best_error) best_error = error, best = candidate;
  }
  if (cleared == 0) return false;
  q = best;
  return true;
}

bool BaseSampler::clear_of_furniture(const Eigen::VectorXd& q) const {
  PoseVector links;
  forward_kinematics(scene_.robot.model, q, scene_.robot.base, links);
  for (const Box& b : robot_) {
    const Pose at = links[static_cast<size_t>(b.link)] * b.pose;
    for (const Box& f : furniture_)
      if (boxes_overlap(at, b.half, f.pose, f.half)) return false;
  }
  return true;
}

}  // namespace demoplan
