#include "core/model/inverse_kinematics.h"

#include <array>
#include <cmath>
#include <stdexcept>

#include "core/model/kinematics.h"

namespace demoplan {

IkSolver::IkSolver(IkProblem problem, IkOptions options)
    : problem_(std::move(problem)), options_(options) {
  const RobotModel& m = *problem_.model;
  std::vector<int> joints;
  for (int l = problem_.link; l != problem_.root_link; l = m.joints[m.links[l].parent_joint].parent_link) {
    if (m.links[l].parent_joint < 0) throw std::invalid_argument("IkProblem: root_link is not an ancestor of link");
    joints.insert(joints.begin(), m.links[l].parent_joint);
  }
  if (problem_.active.size() > static_cast<size_t>(kMaxJoints))
    throw std::invalid_argument("IkProblem: more than " + std::to_string(kMaxJoints) + " active joints");
  std::vector<int> column_of(m.nq, -1);
  for (size_t c = 0; c < problem_.active.size(); ++c) column_of[problem_.active[c]] = static_cast<int>(c);
  // Fold fixed joints into the next moving joint's origin; the tail goes into the frame.
  Pose pending = Pose::Identity();
  for (int j : joints) {
    const Joint& joint = m.joints[j];
    pending = pending * joint.origin;
    if (joint.q_index < 0) continue;
    chain_.push_back({pending.linear(), pending.translation(), joint.axis, joint.q_index,
                      column_of[joint.q_index], joint.type == JointType::Prismatic});
    pending = Pose::Identity();
  }
  tail_ = pending * problem_.link_T_frame;
  lower_ = m.lower_limits();
  upper_ = m.upper_limits();
}

// Walks the chain with plain 3x3 matrices (cheaper than composing Isometry3d); records the
// world axis and origin of every active joint when `axes` is given.
template <typename AxisSink>
Pose IkSolver::evaluate(const Eigen::VectorXd& q, AxisSink&& sink) const {
  Eigen::Matrix3d R = problem_.base.linear();
  Eigen::Vector3d p = problem_.base.translation();
  for (const ChainJoint& c : chain_) {
    p += R * c.p;
    R = R * c.R;
    const Eigen::Vector3d w = R * c.axis;
    sink(c, w, p);
    const double v = q[c.q_index];
    if (c.prismatic) {
      p += v * w;
    } else {
      R = R * Eigen::AngleAxisd(v, c.axis).toRotationMatrix();
    }
  }
  Pose F = Pose::Identity();
  F.translation() = p + R * tail_.translation();
  F.linear() = R * tail_.linear();
  return F;
}

Pose IkSolver::frame_pose(const Eigen::VectorXd& q) const {
  return evaluate(q, [](const ChainJoint&, const Eigen::Vector3d&, const Eigen::Vector3d&) {});
}

// e = (target position - position, log3(R_target R^T)) in world coordinates; J maps active
// joint velocities to the frame's world linear and angular velocity.
void IkSolver::residual(const Eigen::VectorXd& q, const Pose& target, Vector6d& e,
                        Jacobian* J) const {
  struct Axis {
    Eigen::Vector3d direction, origin;
    int column;
    bool prismatic;
  };
  std::array<Axis, kMaxJoints> axes;
  int count = 0;
  const Pose F = evaluate(q, [&](const ChainJoint& c, const Eigen::Vector3d& w, const Eigen::Vector3d& p) {
    if (c.column >= 0 && J) axes[count++] = {w, p, c.column, c.prismatic};
  });
  e.head<3>() = target.translation() - F.translation();
  e.tail<3>() = log3(target.linear() * F.linear().transpose());
  if (!J) return;
  J->setZero(6, static_cast<long>(problem_.active.size()));
  for (int k = 0; k < count; ++k) {
    const Axis& a = axes[k];
    if (a.prismatic) {
      J->col(a.column).head<3>() = a.direction;
    } else {
      J->col(a.column).head<3>() = a.direction.cross(F.translation() - a.origin);
      J->col(a.column).tail<3>() = a.direction;
    }
  }
}

bool IkSolver::descend(const Pose& target, Eigen::VectorXd& q, IkResult& result) const {
  Vector6d e, e2;
  Jacobian J, J2;
  residual(q, target, e, &J);
  double err = e.squaredNorm();
  double lambda = options_.initial_damping;
  const auto n = static_cast<long>(problem_.active.size());
  Eigen::VectorXd candidate = q;
  for (int it = 0; it < options_.max_iterations; ++it) {
    ++result.iterations;
    if (e.head<3>().norm() < options_.tolerance && e.tail<3>().norm() < options_.tolerance) return true;
    // dq = J^T (J J^T + lambda I)^-1 e: 6x6 solve whatever the number of joints.
    Eigen::Matrix<double, 6, 6> A = J * J.transpose();
    A.diagonal().array() += lambda;
    Eigen::Matrix<double, Eigen::Dynamic, 1, 0, kMaxJoints, 1> dq = J.transpose() * A.ldlt().solve(e);
    // A bounded step keeps the linearisation honest far from the target.
    if (const double norm = dq.norm(); norm > options_.max_step) dq *= options_.max_step / norm;
    candidate = q;
    for (long c = 0; c < n; ++c) {
      const int i = problem_.active[c];
      candidate[i] = std::clamp(q[i] + dq[c], lower_[i], upper_[i]);
    }
    residual(candidate, target, e2, &J2);
    const double err2 = e2.squaredNorm();
    if (err2 < err) {
      q = candidate, e = e2, J = J2, err = err2;
      lambda = std::max(lambda * 0.1, 1e-9);
    } else {
      lambda *= 10.0;
      if (lambda > 1e3) break;  // stuck against a limit or in a singular pocket
    }
  }
  return e.head<3>().norm() < options_.tolerance && e.tail<3>().norm() < options_.tolerance;
}

IkResult IkSolver::solve(const Pose& target, const Eigen::VectorXd& seed, std::mt19937_64& rng) const {
  IkResult result;
  std::uniform_real_distribution<double> u(0.0, 1.0);
  Eigen::VectorXd q = seed;
  for (result.attempts = 1; result.attempts <= options_.max_attempts; ++result.attempts) {
    if (result.attempts > 1) {
      for (int i : problem_.active) {
        const double lo = std::isfinite(lower_[i]) ? lower_[i] : -M_PI;
        const double hi = std::isfinite(upper_[i]) ? upper_[i] : M_PI;
        q[i] = lo + u(rng) * (hi - lo);
      }
    }
    for (int i : problem_.active) q[i] = std::clamp(q[i], lower_[i], upper_[i]);
    if (descend(target, q, result)) {
      result.success = true;
      break;
    }
  }
  result.attempts = std::min(result.attempts, options_.max_attempts);
  Vector6d e;
  residual(q, target, e, nullptr);
  result.position_error = e.head<3>().norm();
  result.rotation_error = e.tail<3>().norm();
  result.q = std::move(q);
  return result;
}

}  // namespace demoplan
