#pragma once
// Places a frame of a robot link at a target pose: damped least squares with Levenberg-
// Marquardt damping, joint limits by clamping, random restarts. Success means the residual is
// below the tolerance in metres and in radians; otherwise the result says so.
#include <Eigen/Core>
#include <random>
#include <vector>

#include "core/model/robot_model.h"

namespace demoplan {

struct IkOptions {
  double tolerance = 1e-6;   // m and rad
  int max_iterations = 100;   // per attempt
  int max_attempts = 16;      // the seed first, then random restarts within the limits
  double initial_damping = 1e-3;
  double max_step = 0.5;     // largest joint step per iteration (rad or m, Euclidean)
};

// The frame to place: `link_T_frame` in link `link`, relative to link `root_link` placed at
// `base` (the model's root and the world by default; a robot link when the target moves with
// it, e.g. an object on a mobile robot's deck). Only the configuration slots in `active`
// move; the others keep the seed's values.
struct IkProblem {
  const RobotModel* model = nullptr;
  Pose base = Pose::Identity();
  int root_link = 0;
  int link = -1;
  Pose link_T_frame = Pose::Identity();
  std::vector<int> active;  // configuration indices that may change
};

struct IkResult {
  bool success = false;
  Eigen::VectorXd q;
  double position_error = 0.0;  // m
  double rotation_error = 0.0;  // rad
  int attempts = 0;
  int iterations = 0;  // over all attempts
};

// The chain of joints from the root to `problem.link`, precomputed once per problem.
class IkSolver {
public:
  explicit IkSolver(IkProblem problem, IkOptions options = {});

  IkResult solve(const Pose& target, const Eigen::VectorXd& seed, std::mt19937_64& rng) const;
  // World pose of the frame at q.
  Pose frame_pose(const Eigen::VectorXd& q) const;
  const IkProblem& problem() const { return problem_; }

  static constexpr int kMaxJoints = 32;  // active joints; fixed-capacity matrices avoid heap use

private:
  using Jacobian = Eigen::Matrix<double, 6, Eigen::Dynamic, 0, 6, kMaxJoints>;
  // One LM descent from q; returns true when it converged.
  bool descend(const Pose& target, Eigen::VectorXd& q, IkResult& result) const;
  void residual(const Eigen::VectorXd& q, const Pose& target, Vector6d& e, Jacobian* J) const;

  // A moving joint of the chain with the fixed transforms before it folded into its origin.
  struct ChainJoint {
    Eigen::Matrix3d R;
    Eigen::Vector3d p;
    Eigen::Vector3d axis;
    int q_index;
    int column;  // Jacobian column, -1 when the joint is not active
    bool prismatic;
  };
  template <typename AxisSink>
  Pose evaluate(const Eigen::VectorXd& q, AxisSink&& sink) const;

  IkProblem problem_;
  IkOptions options_;
  std::vector<ChainJoint> chain_;  // root -> link
  Pose tail_ = Pose::Identity();   // last moving joint -> frame
  Eigen::VectorXd lower_, upper_;
};

}  // namespace demoplan
