#pragma once
// Samples configurations that satisfy the constraints of a state or of a transition:
// placement states leave the robot free, grasp states hold the fingers open, transitions
// put the gripper frame on the handle frame (damped least squares, random restarts) and add
// the straight approach or retreat along the handle's approach axis.
#include <map>
#include <memory>
#include <random>
#include <string>

#include "core/graph/base_sampler.h"
#include "core/graph/constraint_graph.h"
#include "core/model/inverse_kinematics.h"

namespace demoplan {

struct ProjectorOptions {
  IkOptions ik{1e-6, 25, 1};  // onto the handle from the seed
  // The approach is followed in steps of at most this length, each solved from the previous
  // one; between two steps the joint-space segment must stay within `straightness` of the axis.
  double approach_step = 0.01;  // m
  double straightness = 0.001;  // m
  int follow_iterations = 15;
  // A mobile base (mobile_base.h): this fraction of the random seeds stays uniform within the
  // joint limits, so nothing the base sampler misses becomes unreachable; the others come
  // from the base sampler. Robots without one draw every seed uniformly, as before.
  double uniform_base_fraction = 0.5;
  BaseSamplerOptions base;
};

// The pair (q_from, q_to) of the paper for one transition, with the straight move between
// them. For a grasp transition q_from is the pre-grasp configuration (in the placement state)
// and q_to the grasp (in the grasp state); for a release, q_from is the release (grasp state)
// and q_to the retreat (placement). `path` runs from q_from to q_to along the approach axis.
struct TransitionSample {
  bool ok = false;
  std::string failure;  // why, when not ok
  int transition = -1;
  std::vector<Eigen::VectorXd> path;
  int state_from = -1, state_to = -1;

  const Eigen::VectorXd& q_from() const { return path.front(); }
  const Eigen::VectorXd& q_to() const { return path.back(); }
  int ik_attempts = 0;
  int ik_iterations = 0;
};

class ConstraintProjector {
public:
  ConstraintProjector(const Scene& scene, const ConstraintGraph& graph, ProjectorOptions options = {});

  // A random configuration of the state: uniform within the joint limits; grasp states keep
  // the gripper open.
  Eigen::VectorXd sample_configuration(int state, std::mt19937_64& rng) const;
  // Samples the transition from a random seed configuration: uniform, or for a mobile base
  // mostly with the base placed from the handle's reach (base_sampler.h).
  TransitionSample sample_on_transition(int transition, std::mt19937_64& rng) const;
  // The same from a given seed (the nearest tree node, say).
  TransitionSample sample_on_transition(int transition, const Eigen::VectorXd& seed,
                                        std::mt19937_64& rng) const;

  // Puts the gripper on the transition's handle from `seed` (the constraint projection).
  IkResult project(int transition, const Eigen::VectorXd& seed, std::mt19937_64& rng) const;
  // Gripper-to-handle error (position m, rotation rad) of a transition's contact configuration.
  std::pair<double, double> handle_residual(int transition, const Eigen::VectorXd& q) const;
  // Where the gripper frame must be for the transition's contact, in the frame of `link`
  // (-1: world): the handle of the object at its placement.
  Pose handle_target(int transition, int* link) const;

  // Null for a robot without a mobile base.
  const BaseSampler* base_sampler() const { return base_sampler_.get(); }
  const ConstraintGraph& graph() const { return graph_; }
  const Scene& scene() const { return scene_; }

private:
  struct Solvers {
    std::unique_ptr<IkSolver> reach;   // from an arbitrary seed
    std::unique_ptr<IkSolver> follow;  // one short descent from a nearby configuration
    // The arm alone, the base kept where the base sampler put it (mobile bases only): let loose,
    // the base would trade the seed's clearance for a smaller step.
    std::unique_ptr<IkSolver> reach_arm;
  };
  const Solvers& solvers_for(int link) const { return solvers_.at(link); }
  void open_gripper(Eigen::VectorXd& q) const;
  // sample_on_transition from a seed; `base_placed`: the base sampler placed the base.
  TransitionSample sample_from(int transition, const Eigen::VectorXd& seed, bool base_placed,
                               std::mt19937_64& rng) const;

  const Scene& scene_;
  const ConstraintGraph& graph_;
  ProjectorOptions options_;
  std::map<int, Solvers> solvers_;  // by reference link (-1: world)
  Eigen::VectorXd lower_, upper_;
  std::unique_ptr<BaseSampler> base_sampler_;
};

}  // namespace demoplan
