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

// The frame to place: `link_T_frame` in link `link`, the robot's root at `base`. Only the
// configuration slots in `active` move; the others keep the seed's values.
struct IkProblem {
  const RobotModel* model = nullptr;
  Pose base = Pose::Identity();
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

private:
  // One LM descent from q; returns true when it converged.
  bool descend(const Pose& target, Eigen::VectorXd& q, IkResult& result) const;
  void residual(const Eigen::VectorXd& q, const Pose& target, Vector6d& e, Eigen::MatrixXd* J) const;

  IkProblem problem_;
  IkOptions options_;
  std::vector<int> chain_;       // joints root -> link
  std::vector<int> column_of_;   // configuration index -> Jacobian column, -1 if inactive
  Eigen::VectorXd lower_, upper_;
};

}  // namespace demoplan
