#include "core/model/inverse_kinematics.h"

#include <cmath>

#include "core/model/kinematics.h"

namespace demoplan {

IkSolver::IkSolver(IkProblem problem, IkOptions options)
    : problem_(std::move(problem)), options_(options) {
  const RobotModel& m = *problem_.model;
  for (int l = problem_.link; m.links[l].parent_joint >= 0; l = m.joints[m.links[l].parent_joint].parent_link)
    chain_.insert(chain_.begin(), m.links[l].parent_joint);
  column_of_.assign(m.nq, -1);
  for (size_t c = 0; c < problem_.active.size(); ++c) column_of_[problem_.active[c]] = static_cast<int>(c);
  lower_ = m.lower_limits();
  upper_ = m.upper_limits();
}

Pose IkSolver::frame_pose(const Eigen::VectorXd& q) const {
  const RobotModel& m = *problem_.model;
  Pose T = problem_.base;
  for (int j : chain_) {
    const Joint& joint = m.joints[j];
    T = joint.q_index < 0 ? T * joint.origin : T * joint.origin * joint_motion(joint, q[joint.q_index]);
  }
  return T * problem_.link_T_frame;
}

// e = (target position - position, log3(R_target R^T)) in world coordinates; J maps active
// joint velocities to the frame's world linear and angular velocity.
void IkSolver::residual(const Eigen::VectorXd& q, const Pose& target, Vector6d& e,
                        Eigen::MatrixXd* J) const {
  const RobotModel& m = *problem_.model;
  struct Axis {
    Eigen::Vector3d direction, origin;
    int column;
    bool prismatic;
  };
  thread_local std::vector<Axis> axes;
  axes.clear();
  Pose T = problem_.base;
  for (int j : chain_) {
    const Joint& joint = m.joints[j];
    T = T * joint.origin;
    if (joint.q_index >= 0) {
      if (column_of_[joint.q_index] >= 0)
        axes.push_back({T.linear() * joint.axis, T.translation(), column_of_[joint.q_index],
                        joint.type == JointType::Prismatic});
      T = T * joint_motion(joint, q[joint.q_index]);
    }
  }
  const Pose F = T * problem_.link_T_frame;
  e.head<3>() = target.translation() - F.translation();
  e.tail<3>() = log3(target.linear() * F.linear().transpose());
  if (!J) return;
  J->setZero(6, static_cast<long>(problem_.active.size()));
  for (const Axis& a : axes) {
    if (a.prismatic) {
      J->col(a.column).head<3>() = a.direction;
    } else {
      J->col(a.column).head<3>() = a.direction.cross(F.translation() - a.origin);
      J->col(a.column).tail<3>() = a.direction;
    }
  }
}

bool IkSolver::descend(const Pose& target, Eigen::VectorXd& q, IkResult& result) const {
  Vector6d e;
  Eigen::MatrixXd J;
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
    Eigen::VectorXd dq = J.transpose() * A.ldlt().solve(e);
    // A bounded step keeps the linearisation honest far from the target.
    if (const double norm = dq.norm(); norm > options_.max_step) dq *= options_.max_step / norm;
    candidate = q;
    for (long c = 0; c < n; ++c) {
      const int i = problem_.active[c];
      candidate[i] = std::clamp(q[i] + dq[c], lower_[i], upper_[i]);
    }
    Vector6d e2;
    Eigen::MatrixXd J2;
    residual(candidate, target, e2, &J2);
    const double err2 = e2.squaredNorm();
    if (err2 < err) {
      q = candidate, e = e2, J = std::move(J2), err = err2;
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
